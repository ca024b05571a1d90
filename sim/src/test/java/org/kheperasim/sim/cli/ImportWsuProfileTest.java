package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.robot.RobotTypes;

/** {@code import-wsu MAP --profile wsu}: the arena's robot line names the {@code wsu} robot, which runs with the profile. */
class ImportWsuProfileTest {
    @TempDir
    Path dir;

    private static byte[] world() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (java.io.ObjectOutputStream o = new java.io.ObjectOutputStream(bytes)) {
            java.util.Vector<Object> v = new java.util.Vector<>();
            v.add(new edu.wsu.KheperaSimulator.Vertex(5, 1, 100, 100, 0, java.awt.Color.RED));
            o.writeObject(v);
        }
        return bytes.toByteArray();
    }

    private int main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        try {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            return Main.commandLine().execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    @Test
    void theProfileOptionWritesTheWsuRobotLine() throws Exception {
        Path map = Files.write(dir.resolve("lab"), world());
        Path plain = dir.resolve("plain.arena");
        Path wsu = dir.resolve("wsu.arena");
        assertEquals(0, main("import-wsu", map.toString(), "-o", plain.toString()));
        assertEquals(0, main("import-wsu", map.toString(), "-o", wsu.toString(), "--profile", "wsu"));
        Arena a = ArenaFormat.parse(Files.readString(plain), plain.toString());
        Arena b = ArenaFormat.parse(Files.readString(wsu), wsu.toString());
        assertSame(RobotTypes.KHEPERA1, a.robotType(0), "without the option, the real robot");
        assertSame(RobotTypes.WSU, b.robotType(0));
        assertTrue(Files.readString(wsu).lines().anyMatch(l -> l.startsWith("robot ") && l.endsWith(" wsu")), Files.readString(wsu));
        assertEquals(2, main("import-wsu", map.toString(), "-o", wsu.toString(), "--profile", "ksuite"));
    }
}
