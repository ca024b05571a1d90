package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * A reference grading that a test makes beside its own, through the same command line ({@code grade ...}) in a JVM of its
 * own: the two share nothing (not System.out, which the tests capture, nor the grader's statics), and while one waits (a
 * hang timeout, a wall-clock limit, a JVM starting) the other works. In the sandbox where there is one, as the tests'
 * own gradings; {@link #await} checks it ended with status 0.
 */
final class ChildGrading implements AutoCloseable {
    private final Process process;
    private final Path log;

    private ChildGrading(Process process, Path log) {
        this.process = process;
        this.log = log;
    }

    /**
     * @param log  where its output goes (read back by {@link #await})
     * @param args what follows {@code grade} on the command line
     */
    static ChildGrading start(Path log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "grade"));
        cmd.addAll(List.of(args));
        if (!BoxProbe.unavailable().isEmpty()) {
            cmd.add("--no-sandbox");
        }
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        return new ChildGrading(p, log);
    }

    /** Waits for the grading to end (at most {@code seconds}); @return what it printed @throws AssertionError unless it exited 0 */
    String await(long seconds) throws IOException, InterruptedException {
        boolean ended = process.waitFor(seconds, TimeUnit.SECONDS);
        if (!ended) {
            process.destroyForcibly().waitFor();
        }
        String text = Files.readString(log, StandardCharsets.UTF_8);
        assertTrue(ended, "the reference grading did not end within " + seconds + " s: " + text);
        assertEquals(0, process.exitValue(), text);
        return text;
    }

    /** Kills the grading if it still runs (a test that failed before it awaited it). */
    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            process.destroyForcibly().waitFor();
        }
    }
}
