package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;

/** {@code import-wsu MAP [-o NAME.arena]} as a user runs it. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ImportWsuCommandTest {
    @TempDir
    Path dir;

    private String out;
    private String err;

    private int main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            return Main.commandLine().execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
    }

    /** A world with one vertical wall at (100, 100) px and one light whose body covers the robot's start. */
    private static byte[] world() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (java.io.ObjectOutputStream o = new java.io.ObjectOutputStream(bytes)) {
            java.util.Vector<Object> v = new java.util.Vector<>();
            v.add(new edu.wsu.KheperaSimulator.Vertex(5, 1, 100, 100, 0, java.awt.Color.RED));
            v.add(new edu.wsu.KheperaSimulator.Vertex(6, 4, 255, 255, 0, java.awt.Color.ORANGE));
            o.writeObject(v);
        }
        return bytes.toByteArray();
    }

    @Test
    void writesAnArenaFileNamingItsSourceThatLoadsAsTheWorldDoes() throws Exception {
        Path map = dir.resolve("course-map");
        Files.write(map, world());
        Path target = dir.resolve("mine.arena");

        assertEquals(0, main("import-wsu", map.toString(), "-o", target.toString()), err);

        String text = Files.readString(target);
        assertTrue(text.startsWith("# Imported from the WSU Khepera Simulator world file course-map by khepera-sim"
                + " import-wsu"), text);
        assertTrue(text.contains("# warning: the original's robot start"), "warnings are kept as comments: " + text);
        assertTrue(text.contains("\nname mine\n"), "named after the output file: " + text);
        Arena written = ArenaFormat.load(target);
        Arena direct = ArenaFiles.load(map, w -> { });
        assertEquals(new Arena("mine", direct.width(), direct.height(), direct.robots(), direct.walls(),
                direct.lights(), direct.caps(), direct.regions()), written);
        assertTrue(out.contains("wrote " + target + " from " + map + ": 1 walls, 0 caps, 0 balls, 1 lights in the file"),
                out);
        assertTrue(err.contains(map + ": warning: the original's robot start"), err);
    }

    @Test
    void itSavesAsEveryFileIsSavedKeepingALinkAndTheFilesMode() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(java.nio.file.FileSystems.getDefault().supportedFileAttributeViews()
                .contains("posix"), "this file system has no POSIX permissions (not Linux or macOS)");
        Path map = dir.resolve("course-map");
        Files.write(map, world());
        // A new file gets the usual mode (the process's umask), not a temporary file's 0600.
        Path fresh = dir.resolve("fresh.arena");
        assertEquals(0, main("import-wsu", map.toString(), "-o", fresh.toString()), err);
        java.util.Set<java.nio.file.attribute.PosixFilePermission> perms = Files.getPosixFilePermissions(fresh);
        assertTrue(perms.contains(java.nio.file.attribute.PosixFilePermission.OTHERS_READ)
                || perms.contains(java.nio.file.attribute.PosixFilePermission.GROUP_READ)
                || !defaultsAreReadable(), "a new arena file is readable as any other file: " + perms);
        // An existing file keeps its mode; a link stays a link and its target gets the arena.
        Path real = dir.resolve("shared.arena");
        Files.writeString(real, "old");
        Files.setPosixFilePermissions(real, java.nio.file.attribute.PosixFilePermissions.fromString("rw-rw-r--"));
        Path link = Files.createSymbolicLink(dir.resolve("mine.arena"), real.getFileName());
        assertEquals(0, main("import-wsu", map.toString(), "-o", link.toString()), err);
        assertTrue(Files.isSymbolicLink(link), "the link is still a link");
        assertTrue(Files.readString(real).contains("# Imported from the WSU Khepera Simulator"), "its target got the arena");
        assertEquals("rw-rw-r--", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
    }

    /** @return true when a file made now is readable by group or others (the umask allows it) */
    private boolean defaultsAreReadable() throws IOException {
        Path probe = Files.createFile(dir.resolve("probe"));
        String p = java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(probe));
        return p.charAt(3) == 'r' || p.charAt(6) == 'r';
    }

    @Test
    void withoutOutputItWritesTheMapsNameDotArenaInTheCurrentFolder() throws Exception {
        Path map = dir.resolve("gates");
        Files.write(map, world());
        Path expected = Path.of("gates.arena");
        assertFalse(Files.exists(expected), "the test would overwrite " + expected.toAbsolutePath());
        try {
            assertEquals(0, main("import-wsu", map.toString()), err);
            assertTrue(Files.readString(expected).contains("\nname gates\n"));
        } finally {
            Files.deleteIfExists(expected);
        }
    }

    @Test
    void aDamagedMapFailsWithTheByteAndWritesNothing() throws Exception {
        Path map = dir.resolve("damaged");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream d = new DataOutputStream(bytes);
        d.writeShort(0xACED);
        d.writeShort(5);
        d.writeByte(0x6A);
        Files.write(map, bytes.toByteArray());
        Path target = dir.resolve("damaged.arena");

        assertEquals(2, main("import-wsu", map.toString(), "-o", target.toString()));

        assertTrue(err.startsWith("khepera-sim: error: " + map + ": byte 4: 0x6A is no tag"), err);
        assertFalse(Files.exists(target));
    }

    @Test
    void theMapItselfIsNeverOverwritten() throws Exception {
        Path map = dir.resolve("world");
        Files.write(map, world());
        assertEquals(2, main("import-wsu", map.toString(), "-o", map.toString()));
        assertTrue(err.contains("is the WSU world file itself"), err);
        assertTrue(ArenaFiles.isWsuWorld(map));
        assertEquals(2, main("import-wsu", dir.resolve("absent").toString()));
        assertTrue(err.contains("no WSU world file"), err);
    }
}
