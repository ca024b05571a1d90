package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolVersion;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.EditLog;

/** Issue 14: every number and file on the command line is checked; errors share one prefix and exit code. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CommandLineInputsTest {
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
            var cl = Main.commandLine();
            cl.setOut(new java.io.PrintWriter(System.out, true));
            cl.setErr(new java.io.PrintWriter(System.err, true));
            return cl.execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
    }

    private int run(String... more) {
        String[] args = new String[6 + more.length];
        System.arraycopy(new String[] {"run", "--arena", "lab", "--controller", "Braitenberg", "--quiet"}, 0, args, 0, 6);
        System.arraycopy(more, 0, args, 6, more.length);
        return main(args);
    }

    @Test
    void hangTimeoutSecondsAndSampleMustBePositiveFiniteDecimals() {
        for (String bad : new String[] {"-1", "0", "NaN", "Infinity", "0x1p3", "1e999"}) {
            assertEquals(ExitCodes.BAD_INPUT, run("--hang-timeout", bad), bad);
            assertTrue(err.startsWith("khepera-sim: error: Invalid value for option '--hang-timeout'"), err);
            assertEquals(ExitCodes.BAD_INPUT, run("--seconds", bad), bad);
            assertTrue(err.contains("'--seconds'"), err);
        }
        assertEquals(ExitCodes.BAD_INPUT, run("--sample-ms", "0"));
        assertEquals(ExitCodes.BAD_INPUT, run("--seed", "0x10"));
        assertEquals(ExitCodes.BAD_INPUT, run("--noise", "NaN"));
        assertTrue(err.contains("See 'khepera-sim run --help'"), err);
    }

    @Test
    void settingsAndBaudArePlainDecimals() {
        assertEquals(ExitCodes.BAD_INPUT, run("--set", "link.baud=0x1p10"));
        assertTrue(err.startsWith("khepera-sim: error: setting link.baud=0x1p10: not a decimal number"), err);
        assertEquals(ExitCodes.BAD_INPUT, run("--set", "prox.3.gain=1d"));
        assertEquals(ExitCodes.BAD_INPUT, run("--set", "prox.3.gain=NaN"));
        assertEquals(ExitCodes.BAD_INPUT, run("--baud", "12345"));
        assertTrue(err.contains("not a Khepera line speed; give one of [9600, 19200, 38400, 57600, 115200]"), err);
        assertEquals(ExitCodes.OK, run("--baud", "9600", "--set", "prox.3.gain=1.5e-1", "--seconds", "1"), err);
    }

    @Test
    void anEditOffTheTickGridIsRefusedNamingItsLine(@TempDir Path dir) throws Exception {
        String arena = ArenaFormat.write(ArenaFormat.loadBundled("lab"));
        Path edits = dir.resolve("run.edits");
        Files.writeString(edits, EditLog.HEADER + "\n@ 10000000001\n" + arena + "end\n");
        assertEquals(ExitCodes.BAD_INPUT, run("--seconds", "60", "--edits", edits.toString()));
        assertTrue(err.startsWith("khepera-sim: error: " + edits + ":2: edit time 10000000001 ns is not on the engine's 1 ms"
                + " tick grid"), err);

        Files.writeString(edits, EditLog.HEADER + "\n@ -5000000\n" + arena + "end\n");
        assertEquals(ExitCodes.BAD_INPUT, run("--seconds", "60", "--edits", edits.toString()));
        assertTrue(err.contains(edits + ":2: '@ -5000000' needs a whole, non-negative number"), err);

        Files.writeString(edits, EditLog.HEADER + "\n@ 70000000000\n" + arena + "end\n");
        assertEquals(ExitCodes.BAD_INPUT, run("--seconds", "60", "--edits", edits.toString()));
        assertTrue(err.contains(edits + ":2: the edit at 70.000 s (70000000000 ns) comes after the end of the run at 60.000 s"),
                err);

        Files.writeString(edits, EditLog.HEADER + "\n@ 10000000000\n" + arena.replace("robot ", "robot x") + "end\n");
        assertEquals(ExitCodes.BAD_INPUT, run("--seconds", "60", "--edits", edits.toString()));
        assertTrue(err.contains(edits + ":6: in the arena of the edit at line 2: robot x is 'x"), err);

        Files.writeString(edits, EditLog.HEADER + "\n@ 10000000000\n" + arena + "end\n");
        assertEquals(ExitCodes.OK, run("--seconds", "60", "--edits", edits.toString()), err);
        assertTrue(out.contains("60.0 s simulated"), "the replay runs its whole length: " + out);
    }

    @Test
    void helpListAndReadmeAgreeOnTheBundledArenasAndControllers() throws Exception {
        assertEquals(ExitCodes.OK, main("list"));
        String list = out;
        assertEquals(ExitCodes.OK, main("run", "--help"));
        String help = out.replaceAll("\\s+", " ");
        assertTrue(help.contains(ExitCodes.HELP), help);
        String readme = Files.readString(Path.of(System.getProperty("kheperasim.repoRoot", ".."), "README.md"));
        for (String arena : ArenaFormat.bundledNames()) {
            assertTrue(list.contains(arena) && help.contains(arena) && readme.contains("`" + arena + "`"), arena);
        }
        for (String controller : ControllerCatalog.bundled()) {
            assertTrue(list.contains(controller) && help.contains(controller) && readme.contains("`" + controller + "`"),
                    controller);
        }
        try (var files = Files.list(Path.of(System.getProperty("kheperasim.repoRoot", ".."), "arenas"))) {
            assertEquals(files.map(p -> p.getFileName().toString().replace(".arena", "")).sorted().toList(),
                    ArenaFormat.bundledNames().stream().sorted().toList(), "every file in arenas/ is bundled");
        }
    }

    @Test
    void versionComesFromTheBuild() {
        assertEquals(ExitCodes.OK, main("--version"));
        assertTrue(out.startsWith("khepera-sim " + ToolVersion.version()), out);
    }

    @Test
    void aControllerThatFailsExitsOneAndBadInputTwo() {
        assertEquals(ExitCodes.FAILED, main("run", "--arena", "lab", "--controller",
                "org.kheperasim.testcontrollers.Thrower", "--seconds", "5"));
        assertEquals(ExitCodes.BAD_INPUT, main("run", "--arena", "nowhere", "--controller", "Braitenberg"));
        assertTrue(err.startsWith("khepera-sim: error: no arena file 'nowhere'"), err);
    }
}
