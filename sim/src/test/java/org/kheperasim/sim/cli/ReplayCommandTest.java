package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code replay --html}: a trace or a recording becomes a web page; bad input is named with its fix. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ReplayCommandTest {
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

    private Path trace(String arena) {
        Path trace = dir.resolve("run.trace");
        assertEquals(0, main("run", "--arena", arena, "--controller", "Braitenberg", "--seconds", "10", "--seed", "2",
                "--trace", trace.toString(), "--quiet"));
        return trace;
    }

    @Test
    void aTraceBecomesAPage() throws Exception {
        Path trace = trace("lab");
        Path page = dir.resolve("run.html");
        assertEquals(0, main("replay", "--html", page.toString(), trace.toString()), err);
        assertTrue(out.startsWith("wrote " + page + ": ") && out.contains("10.0 s of 1 robot"), out);
        String html = Files.readString(page, StandardCharsets.UTF_8);
        assertTrue(html.startsWith("<!DOCTYPE html>") && html.contains("<title>Braitenberg in lab · seed 2</title>"), html.substring(0, 400));
        assertTrue(err.contains("note: ") && err.contains("arena 'lab' (bundled)"), "says where the arena came from: " + err);
    }

    @Test
    void aTraceWithItsArenaGiven() throws Exception {
        Path arenaFile = dir.resolve("mine.arena");
        Files.writeString(arenaFile, org.kheperasim.sim.arena.ArenaFormat.write(org.kheperasim.testfixtures.Arenas.THREE));
        Path trace = dir.resolve("three.trace");
        assertEquals(0, main("run", "--arena", arenaFile.toString(), "--controller", "Braitenberg", "--seconds", "5",
                "--trace", trace.toString(), "--quiet"));
        Files.delete(arenaFile);
        Path elsewhere = Files.createDirectories(dir.resolve("arenas")).resolve("three.arena");
        Files.writeString(elsewhere, org.kheperasim.sim.arena.ArenaFormat.write(org.kheperasim.testfixtures.Arenas.THREE));
        Path page = dir.resolve("three.html");
        assertEquals(0, main("replay", "--html", page.toString(), "--arena", elsewhere.toString(), trace.toString()), err);
        assertTrue(out.contains("5.0 s of 3 robots"), out);
        assertEquals(2, main("replay", "--html", page.toString(), "--arena", writeLab().toString(), trace.toString()));
        assertTrue(err.contains("is not the arena " + trace + " was recorded in") && err.contains("give the arena file the run used"), err);
    }

    private Path writeLab() throws Exception {
        Path lab = dir.resolve("lab.arena");
        Files.writeString(lab, org.kheperasim.sim.arena.ArenaFormat.write(org.kheperasim.sim.arena.ArenaFormat.loadBundled("lab")));
        return lab;
    }

    @Test
    void badInputIsNamedWithItsFix() throws Exception {
        assertEquals(2, main("replay", "--html", dir.resolve("x.html").toString(), dir.resolve("none.trace").toString()));
        assertTrue(err.contains("khepera-sim: error: no trace or recording " + dir.resolve("none.trace")
                + "; give a trace written by 'run --trace FILE'"), err);
        Path trace = trace("lab");
        assertEquals(2, main("replay", "--html", dir.resolve("no/such/x.html").toString(), trace.toString()));
        assertTrue(err.contains("its folder " + dir.resolve("no/such") + " does not exist; create it or give another path"), err);
        assertEquals(2, main("replay", trace.toString()));
        assertTrue(err.contains("--html"), err);
        Path recording = Files.createDirectories(dir.resolve("recording"));
        assertEquals(2, main("replay", "--html", dir.resolve("x.html").toString(), "--arena", "lab", recording.toString()));
        assertTrue(err.contains("carries its own start.arena; give --arena only with a trace file"), err);
        Path damaged = dir.resolve("damaged.trace");
        String text = Files.readString(trace, StandardCharsets.UTF_8);
        Files.writeString(damaged, text.replaceFirst("\n0\\.050 0 ", "\n0.050 zero "));
        assertEquals(2, main("replay", "--html", dir.resolve("x.html").toString(), damaged.toString()));
        assertTrue(err.matches("(?s)khepera-sim: error: " + java.util.regex.Pattern.quote(damaged.toString()) + ":\\d+: .*"), err);
        assertFalse(Files.exists(dir.resolve("x.html")), "no page from bad input");
    }
}
