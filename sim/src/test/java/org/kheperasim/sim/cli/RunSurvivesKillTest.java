package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.trace.TraceFormatException;
import org.kheperasim.sim.trace.TraceReader;

/**
 * Issue 14, no run is lost: a run in its own JVM is killed while it writes its trace. After
 * kill -9 the trace holds whole lines under a valid header; after SIGTERM the result line is
 * printed too; a controller's System.exit ends the run with a named fault (exit status 1), and the
 * trace is readable.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunSurvivesKillTest {

    @TempDir
    Path dir;

    private Process start(Path trace, String controller, String... more) throws IOException {
        String cp = System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-cp", cp, Main.class.getName(), "run", "--arena", "lab", "--controller", controller,
                "--seed", "7", "--seconds", "100000000", "--sample-ms", "1000", "--quiet", "--trace", trace.toString()));
        cmd.addAll(List.of(more));
        return new ProcessBuilder(cmd).redirectOutput(dir.resolve("out.txt").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
    }

    /** Waits until the trace has at least {@code lines} sample lines (the header has 8). */
    private void awaitSamples(Path trace, int lines, Process p) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
        while (System.nanoTime() < end && p.isAlive()) {
            if (Files.exists(trace) && Files.readAllLines(trace).size() >= 8 + lines) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("no samples in the trace; alive " + p.isAlive() + "; " + read("err.txt"));
    }

    private String read(String name) throws IOException {
        return Files.readString(dir.resolve(name));
    }

    @Test
    void killMinusNineLeavesATraceOfWholeLines() throws Exception {
        Path trace = dir.resolve("killed.trace");
        Process p = start(trace, "Braitenberg");
        try {
            awaitSamples(trace, 20, p);
            p.destroyForcibly(); // SIGKILL: no hook runs
            assertTrue(p.waitFor(30, TimeUnit.SECONDS));
        } finally {
            p.destroyForcibly();
        }
        assertEquals(137, p.exitValue(), "killed by signal 9");
        // Whole lines, but for the last when the kill landed inside a write (Linux stops a write between two
        // pages for SIGKILL): the reader names that line, and the rest reads once it is deleted.
        String text = Files.readString(trace);
        if (!text.endsWith("\n")) {
            TraceFormatException torn = assertThrows(TraceFormatException.class, () -> TraceReader.read(trace));
            assertTrue(torn.getMessage().contains("delete that line to read the rest"), torn.getMessage());
            text = text.substring(0, text.lastIndexOf('\n') + 1);
        }
        TraceReader.Summary s = TraceReader.parse(text, trace.toString());
        assertEquals("7", s.header().get("seed"));
        assertTrue(s.robotLines() >= 20, "lines up to about a second before the kill: " + s.robotLines());
        try (var files = Files.list(dir)) {
            assertEquals(List.of("err.txt", "killed.trace", "out.txt"),
                    files.map(f -> f.getFileName().toString()).sorted().toList(), "no temporary file");
        }
    }

    @Test
    void sigtermPrintsTheResultLineAndFinishesTheTrace() throws Exception {
        Path trace = dir.resolve("stopped.trace");
        Process p = start(trace, "Braitenberg");
        try {
            awaitSamples(trace, 20, p);
            p.destroy(); // SIGTERM: the shutdown hook stops the run
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), read("err.txt"));
        } finally {
            p.destroyForcibly();
        }
        String out = read("out.txt");
        String err = read("err.txt");
        assertTrue(out.startsWith("seed 7"), out);
        String result = out.lines().filter(l -> l.startsWith("Braitenberg in lab: ")).findFirst().orElseThrow(
                () -> new AssertionError("no result line: " + out + err));
        assertTrue(result.contains("; trace sha256 "), result);
        assertTrue(err.contains("khepera-sim: stopped at "), err);
        TraceReader.Summary s = TraceReader.read(trace);
        double simulated = Double.parseDouble(result.replaceAll(".*: ([0-9.]+) s simulated.*", "$1"));
        assertEquals(Math.floor(simulated), s.lastSeconds(), 1.0, "the trace runs to where the run stopped");
        String sha = result.replaceAll(".*trace sha256 ([0-9a-f]{64}).*", "$1");
        byte[] digest = java.security.MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(trace));
        assertEquals(java.util.HexFormat.of().formatHex(digest), sha, "the trace is complete: its hash is the result's");
    }

    @Test
    void aControllerCallingSystemExitLeavesAReadableTrace() throws Exception {
        Path trace = dir.resolve("exited.trace");
        Process p = start(trace, "org.kheperasim.testcontrollers.Exiter", "--hang-timeout", "1");
        try {
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), read("err.txt"));
        } finally {
            p.destroyForcibly();
        }
        // The loader contains the call: the run ends with the named fault and fails (status 1), the
        // process is not ended by the controller.
        assertEquals(1, p.exitValue(), read("err.txt"));
        assertTrue((read("out.txt") + read("err.txt")).contains("called System.exit(3)"), "the fault is named: "
                + read("out.txt") + read("err.txt"));
        TraceReader.Summary s = TraceReader.read(trace);
        assertTrue(s.robotLines() >= 10, "the trace up to the exit: " + s.robotLines() + " lines; " + read("err.txt"));
    }
}
