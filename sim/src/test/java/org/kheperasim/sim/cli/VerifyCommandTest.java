package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.RunRecording;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.trace.LineFileWriter;

/**
 * {@code verify}: a trace and a run recording run again identically; a recording whose settings
 * were changed is caught at the first sample that differs.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class VerifyCommandTest {
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

    @Test
    void theArenaFileOfTheSameNameBesideATraceIsFoundWhenItIsTheRecordedOne() throws Exception {
        Path arena = dir.resolve("three.arena");
        String text = "khepera-arena 1\nname three\nsize 1219.2 1219.2\nlight 600 600\nrobot 300 300 0\nrobot 900 300 90\n";
        Files.writeString(arena, text);
        Path trace = dir.resolve("t.trace");
        assertEquals(ExitCodes.OK, main("run", "--arena", arena.toString(), "--controller", "Braitenberg", "--seed", "2",
                "--seconds", "3", "--quiet", "--trace", trace.toString()), err);
        assertEquals(ExitCodes.OK, main("verify", trace.toString()), err);
        assertTrue(out.startsWith("identical: "), out);
        assertTrue(org.kheperasim.sim.replay.ReplayFiles.open(trace).arena().lights().size() == 1, "the replay draws its lamp");
        // Another arena under that name (edited since) is not taken for the recorded one.
        Files.writeString(arena, text.replace("light 600 600", "light 500 600"));
        assertEquals(ExitCodes.BAD_INPUT, main("verify", trace.toString()));
        assertTrue(err.contains("no arena file 'three'"), err);
        // A stale start.arena beside a trace of a bundled arena is not taken for it either.
        Path lab = dir.resolve("lab.trace");
        assertEquals(ExitCodes.OK, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seed", "2", "--seconds", "2",
                "--quiet", "--trace", lab.toString()), err);
        Files.writeString(dir.resolve("start.arena"), text);
        assertEquals(ExitCodes.OK, main("verify", lab.toString()), err);
    }

    @Test
    void aTraceRunsAgainIdentically() {
        Path trace = dir.resolve("run.trace");
        assertEquals(ExitCodes.OK, main("run", "--arena", "maze", "--controller", "WallFollower", "--seed", "4", "--seconds",
                "30", "--quiet", "--trace", trace.toString()), err);
        assertEquals(ExitCodes.OK, main("verify", trace.toString()), out + err);
        assertTrue(out.startsWith("identical: 601 sample lines up to 30.0 s"), out);
    }

    /** A recording as the window saves one: start arena, edits, settings, replay line, and the run's trace. */
    private Path record(Settings settings) throws Exception {
        Path rec = Files.createDirectories(dir.resolve("recording"));
        RunSession s = new RunSession(ArenaFormat.loadBundled("lab"), "Braitenberg", new ControllerCatalog(List.of()), 8,
                settings, line -> { }, HostOptions.defaults());
        s.trace(LineFileWriter.open(rec.resolve("run.trace")), 100);
        s.runTo(20_000_000_000L);
        s.close();
        RunRecording.save(s, 20, List.of(), settings, rec);
        return rec;
    }

    /**
     * A window recording of a {@code .java} the window compiled: its classes lie in a folder of the
     * window's own, which replay.txt names and which an instructor's machine has not. verify finds
     * them in the recording without --classpath, and again once that folder is gone.
     */
    @Test
    void aRecordingOfAControllerCompiledInTheWindowVerifiesWithoutAClasspath() throws Exception {
        Path src = Files.createDirectories(dir.resolve("src")).resolve("Spinner.java");
        Files.writeString(src, "import org.kheperasim.api.*;\n\npublic class Spinner extends Controller {\n"
                + "    @Override\n    protected void doWork() {\n        setSpeeds(3, proximity(IrSensor.FRONT_LEFT) > 300 ? -3 : 5);\n"
                + "        sleepMillis(100);\n    }\n}\n");
        Path classes = dir.resolve("window-classes").resolve("Spinner-1f");
        var compiled = org.kheperasim.sim.run.ControllerCompiler.compile(src, classes);
        assertTrue(compiled.success(), compiled.report("Spinner.java"));
        Path rec = Files.createDirectories(dir.resolve("spinner-recording"));
        RunSession s = new RunSession(ArenaFormat.loadBundled("lab"), "Spinner", new ControllerCatalog(List.of(classes)), 3,
                Settings.defaults(), line -> { }, HostOptions.defaults());
        s.trace(LineFileWriter.open(rec.resolve("run.trace")), 100);
        s.runTo(10_000_000_000L);
        s.close();
        RunRecording.save(s, 10, List.of(classes), Settings.defaults(), rec);
        assertEquals(List.of(rec.resolve("classes")), RunRecording.classpath(rec), Files.readString(rec.resolve("replay.txt")));

        assertEquals(ExitCodes.OK, main("verify", rec.toString()), out + err);
        assertTrue(out.startsWith("identical: 101 sample lines up to 10.0 s"), out);
        // The window's folder is cleaned away: the recording's own copy still replays.
        try (var files = Files.walk(classes.getParent())) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        }
        assertEquals(ExitCodes.OK, main("verify", rec.toString()), out + err);
        assertTrue(out.startsWith("identical: "), out);
        // A recording whose replay.txt names a classpath that is not there says so.
        Files.writeString(rec.resolve("replay.txt"), Files.readString(rec.resolve("replay.txt"))
                .replace("--classpath classes", "--classpath '/no such/folder'"));
        assertEquals(ExitCodes.BAD_INPUT, main("verify", rec.toString()));
        assertTrue(err.contains("replay.txt names the classpath entry /no such/folder, which does not exist"), err);
    }

    @Test
    void anUntouchedRecordingIsIdenticalAndAChangedSettingIsCaughtAtItsFirstSample() throws Exception {
        Path rec = record(Settings.defaults());
        assertEquals(ExitCodes.OK, main("verify", rec.toString()), out + err);
        assertTrue(out.startsWith("identical: 201 sample lines up to 20.0 s"), out);

        // Someone changes the recording's settings: the left motor runs 5 % slow.
        Files.writeString(rec.resolve("run.settings"), Files.readString(rec.resolve("run.settings"))
                + "motor.left.calibration = 0.95\n");
        // Where must it differ? Run the changed run ourselves and find the first sample line that differs.
        Path changed = dir.resolve("changed.trace");
        assertEquals(ExitCodes.OK, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seed", "8", "--seconds", "20",
                "--sample-ms", "100", "--set", "motor.left.calibration=0.95", "--quiet", "--trace", changed.toString()), err);
        List<String> a = Files.readAllLines(rec.resolve("run.trace")).stream().filter(l -> !l.startsWith("#")).toList();
        List<String> b = Files.readAllLines(changed).stream().filter(l -> !l.startsWith("#")).toList();
        int first = 0;
        while (a.get(first).equals(b.get(first))) {
            first++;
        }
        String time = a.get(first).split(" ")[0];
        assertTrue(first > 0, "the first samples (before the wheels turn) agree");

        assertEquals(ExitCodes.FAILED, main("verify", rec.toString()), out + err);
        assertTrue(out.startsWith("differs: "), out);
        assertTrue(out.contains("header settings: recorded 'defaults', now 'motor.left.calibration=0.95'"), out);
        assertTrue(out.contains("first difference at sample line " + (first + 1) + " (t = " + time + " s, robot 0): "), out);
    }

    @Test
    void aTraceOfAnotherArenaOrAMissingOneIsBadInput() throws Exception {
        Path trace = dir.resolve("lab.trace");
        assertEquals(ExitCodes.OK, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "2", "--quiet",
                "--trace", trace.toString()), err);
        Path other = dir.resolve("other.arena");
        ArenaFormat.save(ArenaFormat.loadBundled("maze"), other);
        assertEquals(ExitCodes.BAD_INPUT, main("verify", trace.toString(), "--arena", other.toString()));
        assertTrue(err.contains("is not the one recorded") && err.contains("--arena FILE"), err);
        assertEquals(ExitCodes.BAD_INPUT, main("verify", dir.resolve("nothing.trace").toString()));
        assertTrue(err.contains("no trace file"), err);
    }
}
