package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.ArenaFormat;

/**
 * Issue 35 item 8: bad input to every reader of the command line (a sparse 2 GB file, {@code /dev/zero},
 * a FIFO, a folder, a number out of range) gets one line on standard error, {@code khepera-sim: error: ...},
 * and exit status 2: no OutOfMemoryError, no hang, no run for ever.
 */
class BadInputReadersTest {
    @TempDir
    static Path dir;

    private static Path big;
    private static Path fifo;

    private String out;
    private String err;

    @BeforeEach
    void files() throws Exception {
        if (big == null) {
            big = dir.resolve("big.trace");
            try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
                f.setLength(2L << 30);   // sparse: 2 GiB that take no disk
            }
            Files.writeString(dir.resolve("lab.arena"), ArenaFormat.write(ArenaFormat.loadBundled("lab")));
        }
        if (fifo == null && new java.io.File("/usr/bin/mkfifo").canExecute()) {
            Path f = dir.resolve("fifo");
            if (new ProcessBuilder("mkfifo", f.toString()).start().waitFor() == 0) {
                fifo = f;
            }
        }
    }

    private int main(String stdin, String... args) {
        InputStream oldIn = System.in;
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int[] code = {-1};
        try {
            System.setIn(new ByteArrayInputStream(stdin.getBytes(StandardCharsets.UTF_8)));
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
                var cl = Main.commandLine();
                cl.setOut(new PrintWriter(System.out, true));
                cl.setErr(new PrintWriter(System.err, true));
                code[0] = cl.execute(args);
            }, () -> "hung: " + String.join(" ", args));
        } finally {
            System.setIn(oldIn);
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
        return code[0];
    }

    /** Runs the command and checks: exit 2, one line on standard error, the error prefix, and the words given. */
    private void refused(String expect, String... args) {
        refusedWithInput("", expect, args);
    }

    private void refusedWithInput(String stdin, String expect, String... args) {
        int code = main(stdin, args);
        String cmd = String.join(" ", args);
        assertEquals(ExitCodes.BAD_INPUT, code, cmd + "\n" + out + err);
        assertEquals(1, err.lines().count(), cmd + ": one line on standard error:\n" + err);
        assertTrue(err.startsWith("khepera-sim: error: "), cmd + ": " + err);
        assertTrue(err.contains(expect), cmd + ": " + err);
    }

    private static List<String> sparseCommands() {
        String b = big.toString();
        String html = dir.resolve("o.html").toString();
        List<String> c = new ArrayList<>();
        c.add("replay --html " + html + " " + b);
        c.add("verify " + b);
        c.add("replay --html " + html + " --arena " + dir.resolve("lab.arena") + " " + b);
        return c;
    }

    @Test
    void aSparseTwoGigabyteTraceIsRefusedBeforeItIsRead() {
        for (String c : sparseCommands()) {
            refused("the file is larger than 256 MiB, the limit for", c.split(" "));
        }
        Path bigArena = dir.resolve("big.arena");
        try (RandomAccessFile f = new RandomAccessFile(bigArena.toFile(), "rw")) {
            f.setLength(2L << 30);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        refused("the limit for arena files", "run", "--arena", bigArena.toString(), "--controller", "Braitenberg", "--seconds", "1");
    }

    @Test
    void devZeroIsRefusedByEveryWholeFileReader() {
        String html = dir.resolve("o.html").toString();
        refused("/dev/zero: this is not a regular file", "replay", "--html", html, "/dev/zero");
        refused("/dev/zero: this is not a regular file", "replay", "--html", html, "--arena", dir.resolve("lab.arena").toString(),
                "/dev/zero");
        refused("/dev/zero: this is not a regular file", "verify", "/dev/zero");
        refused("/dev/zero: this is not a regular file", "run", "--arena", "/dev/zero", "--controller", "Braitenberg");
        refused("/dev/zero: this is not a regular file", "run", "--arena", "lab", "--controller", "Braitenberg", "--edits",
                "/dev/zero");
        // evaluate reads its jobs as they come (a pipe is fine): a "line" without end is refused at the limit.
        refused("/dev/zero:1: the line is longer than", "evaluate", "--jobs", "/dev/zero");
    }

    @Test
    void aFifoIsRefusedWithoutWaitingForAWriter() {
        Assumptions.assumeTrue(fifo != null, "no mkfifo on this machine");
        String f = fifo.toString();
        String html = dir.resolve("o.html").toString();
        refused(f + ": this is not a regular file", "replay", "--html", html, f);
        refused(f + ": this is not a regular file", "replay", "--html", html, "--arena", dir.resolve("lab.arena").toString(), f);
        refused(f + ": this is not a regular file", "verify", f);
        refused(f + ": this is not a regular file", "run", "--arena", f, "--controller", "Braitenberg");
        refused(f + ": this is not a regular file", "run", "--arena", "lab", "--controller", "Braitenberg", "--edits", f);
        refused("no WSU world file " + f, "import-wsu", f, "-o", dir.resolve("x.arena").toString());
        refused("classpath entry " + f + " is neither a folder nor a jar", "run", "--arena", "lab", "--classpath", f,
                "--controller", "Mine", "--seconds", "1");
    }

    @Test
    void aFolderIsNamedAsOne() {
        refused("this is a folder; give the arena file itself", "run", "--arena", dir.toString(), "--controller", "Braitenberg");
        refused("this is a folder; give a job file", "evaluate", "--jobs", dir.toString());
    }

    @Test
    void anArenaOrATraceThatWouldRunForEverIsRefused() throws Exception {
        Path arena = dir.resolve("forever.arena");
        Files.writeString(arena, ArenaFormat.write(ArenaFormat.loadBundled("lab")).replaceFirst("(?m)^time-limit .*$", "")
                + "time-limit 9.2e18\n");
        refused("time-limit is 9200000000000000000 s; give simulated seconds, more than 0 and at most 86400", "run", "--arena",
                arena.toString(), "--controller", "Braitenberg");   // (refused before this issue too)
        Path trace = dir.resolve("short.trace");
        assertEquals(ExitCodes.OK, main("", "run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "1", "--quiet",
                "--trace", trace.toString()), err);
        List<String> lines = new ArrayList<>(Files.readAllLines(trace));
        String last = lines.remove(lines.size() - 1);
        lines.add("999999999999.000" + last.substring(last.indexOf(' ')));
        Files.write(trace, lines);
        refused("is later than any run ends", "verify", trace.toString());
    }

    /** Under the limit but more than the heap holds: the reader says so in one line, not with an OutOfMemoryError's trace. */
    @Test
    void aTraceLargerThanTheHeapIsOneLine() throws Exception {
        Path mid = dir.resolve("mid.trace");
        try (RandomAccessFile f = new RandomAccessFile(mid.toFile(), "rw")) {
            f.setLength(200L << 20);
        }
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx48m",
                "-cp", System.getProperty("java.class.path"), Main.class.getName(), "verify", mid.toString())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        String e = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(ExitCodes.BAD_INPUT, p.waitFor(), e);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("khepera-sim: error: " + mid + ": the file (200 MiB) does not fit in this Java's memory"), e);
    }

    @Test
    void evaluateBoundsTheSimulatedTime() {
        refusedWithInput("{\"controller\": \"StepBraitenberg\", \"arena\": \"lab\", \"seconds\": 9.2e18}\n",
                "1 job line could not be read (first: line 1: \"seconds\": 9.2E18 is out of range; give a simulated time greater"
                        + " than 0 and at most 100000000", "evaluate");
        assertTrue(out.contains("\"status\": \"error\"") || out.contains("\"status\":\"error\""), out);
        int code = main("", "evaluate", "--seconds", "9.2e18", "--jobs", "-");
        assertEquals(ExitCodes.BAD_INPUT, code, err);
        assertTrue(err.startsWith("khepera-sim: error: Invalid value for option '--seconds'"), err);
    }
}
