package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * {@code run --html FILE}: the run's page, recorded as it goes, without changing the run; a
 * controller that threw is on the page with the student's line; a path that cannot be written is
 * refused before the run; in the sandbox the page is made from the boxed run's trace.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunHtmlTest {
    @TempDir
    Path dir;
    private String out;
    private String err;

    @Test
    void theRunsPageIsWrittenAndTheRunIsTheSame() throws Exception {
        Path plain = dir.resolve("plain.trace");
        Path traced = dir.resolve("traced.trace");
        Path page = dir.resolve("maze.html");
        assertEquals(0, main("run", "--arena", "maze", "--controller", "WallFollower", "--seed", "1", "--seconds", "30",
                "--trace", plain.toString()));
        assertEquals(0, main("run", "--arena", "maze", "--controller", "WallFollower", "--seed", "1", "--seconds", "30",
                "--trace", traced.toString(), "--html", page.toString()));
        assertArrayEquals(Files.readAllBytes(plain), Files.readAllBytes(traced), "recording the page does not change the run");
        assertTrue(out.contains("wrote " + page + ": ") && out.contains("30.0 s of 1 robot, poses every 50 ms"), out);
        String html = Files.readString(page);
        assertTrue(html.contains("\"title\":\"WallFollower in maze · seed 1\""), "the page is the run's");
        assertTrue(html.contains("\"endMs\":29950,"), "it shows the run's samples to its last, 50 ms before its end");
        assertTrue(html.contains("\"coverageAtEnd\":true"), "the run's own facts give the page its score");
    }

    @Test
    void aControllerThatThrewIsOnThePageWithTheStudentsLine() throws Exception {
        Path page = dir.resolve("threw.html");
        assertEquals(1, main("run", "--arena", "lab", "--controller", "org.kheperasim.testcontrollers.Thrower", "--seed", "2",
                "--seconds", "5", "--html", page.toString()));
        String html = Files.readString(page);
        assertTrue(html.contains("\"status\":\"failed\",\"message\":\"threw java.lang.ArithmeticException: / by zero"), html);
        assertTrue(html.contains("at org.kheperasim.testcontrollers.Thrower.run(Thrower.java:24)"), "the student's line");
    }

    @Test
    void aPageThatCannotBeWrittenIsRefusedBeforeTheRun() {
        assertEquals(2, main("run", "--arena", "maze", "--controller", "WallFollower", "--html",
                dir.resolve("no/such/run.html").toString()));
        assertTrue(err.contains("--html " + dir.resolve("no/such/run.html") + ": its folder "), err);
        assertFalse(out.contains("seed "), "refused before the run: " + out);
        assertEquals(2, main("run", "--arena", "maze", "--controller", "WallFollower", "--html", dir.toString()));
        assertTrue(err.contains("is a folder; give a file name such as"), err);
    }

    @Test
    void inTheSandboxThePageIsMadeFromTheBoxedRunsTrace() throws Exception {
        BoxProbe.unavailable().ifPresent(reason -> {
            if ("true".equals(System.getenv("CI"))) {
                fail("no sandbox: " + reason + "; CI=true requires the sandbox tests to run (apt-get install -y bubblewrap)");
            }
            Assumptions.assumeTrue(false, "no sandbox (" + reason + "); sandbox test skipped");
        });
        Path page = dir.resolve("boxed.html");
        assertEquals(0, main("run", "--sandbox", "--arena", "maze", "--controller", "WallFollower", "--seed", "1",
                "--seconds", "10", "--html", page.toString()));
        assertTrue(out.contains("wrote " + page + ": ") && out.contains("from the sandboxed run's trace"), out);
        assertTrue(Files.readString(page).contains("\"endMs\":10000,"), "the page replays the boxed run's trace");
        try (var files = Files.list(Path.of(System.getProperty("java.io.tmpdir")))) {
            assertTrue(files.noneMatch(f -> f.getFileName().toString().startsWith("khepera-run-page-")),
                    "the temporary trace is gone");
        }
    }

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
}
