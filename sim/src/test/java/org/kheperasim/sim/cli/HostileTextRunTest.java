package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.text.HostileText;
import org.kheperasim.testfixtures.Cli;

/**
 * Issue 35 item 6: what a controller prints and throws reaches {@code run}'s terminal escaped, every line
 * of its fault stamped as its own, so that no forged result line comes first and the real one is never
 * hidden; the same for {@code --json} and for an error line.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class HostileTextRunTest {
    @TempDir
    Path dir;

    private String out;
    private String err;

    private int main(String... args) {
        Cli.Printed p = Cli.main(args);
        out = p.out();
        err = p.err();
        return p.code();
    }

    private Path compiledForger() throws Exception {
        Path src = HostileText.forger(dir.resolve("src"));
        Path classes = dir.resolve("classes");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), "--release", "17", src.toString()));
        return classes;
    }

    @Test
    void aForgedResultLineIsStampedAndNothingRawReachesTheTerminal() throws Exception {
        Path classes = compiledForger();
        Path page = dir.resolve("run.html");
        int code = main("run", "--arena", "lab", "--classpath", classes.toString(), "--controller", "Forger", "--seconds", "2",
                "--seed", "1", "--html", page.toString());
        assertEquals(ExitCodes.FAILED, code, out + err);
        HostileText.assertNoRawControl("run's standard output", out);
        HostileText.assertNoRawControl("run's standard error", err);
        HostileText.assertNoRawControl("the run's web page", java.nio.file.Files.readString(page));
        String[] outLines = out.split("\n");
        String result = outLines[outLines.length - 2];   // then the page's "wrote ..."
        assertTrue(result.startsWith("Forger in lab: 0.5 s simulated") && result.contains("; controller failed;"), out);
        long resultShaped = (out + err).lines().filter(l -> l.startsWith("Forger in lab:")).count();
        assertEquals(1, resultShaped, "only the real result line starts like one:\n" + out + err);
        assertTrue(err.lines().anyMatch(l -> l.matches("\\[ +0\\.\\d+ s\\] ERROR .*: " + HostileText.FORGED
                + " in 0\\.01 s; controller ok\\\\e\\[8m\\\\x07")), "the forged line, stamped and escaped:\n" + err);
        assertTrue(out.contains("bell\\x07 nul\\x00 cr\\r esc\\e[2J\\e[H rlo\\u202eevil del\\x7f c1\\x85 sep\\u2028"), out);
        assertTrue(err.contains("err \\e[31mred\\rover"), err);
        assertTrue(err.lines().anyMatch(l -> l.matches("\\[ +0\\.\\d+ s\\] ERROR .*:     at Forger\\.doWork\\(Forger\\.java:\\d+\\)")),
                "the stack trace's lines are stamped too, indented:\n" + err);
    }

    @Test
    void theJsonResultHoldsNoRawControlEither() throws Exception {
        Path classes = compiledForger();
        main("run", "--arena", "lab", "--classpath", classes.toString(), "--controller", "Forger", "--seconds", "2", "--json");
        HostileText.assertNoRawControl("run --json's output", out);
        HostileText.assertNoRawControl("run --json's errors", err);
        assertTrue(out.contains("controller ok\\u001b[8m\\u0007"), out);
    }

    @Test
    void anErrorLineIsOneLineWhateverTheMessageHolds() throws Exception {
        Path classes = compiledForger();
        // A controller name with a line end and ESC: the error names it, on one line.
        int code = main("run", "--arena", "lab", "--classpath", classes.toString(), "--controller", "No\nSuch\u001b[2J", "--seconds", "1");
        assertEquals(ExitCodes.BAD_INPUT, code, err);
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.startsWith("khepera-sim: error: ") && err.contains("No\\nSuch\\e[2J"), err);
    }
}
