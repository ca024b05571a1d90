package org.kheperasim.sim.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.run.Simulation;

/** What can be replayed is read back exactly: recordings, traces (whole or cut short) and real robots' recordings. */
class ReplayFilesTest {
    @TempDir
    Path dir;

    private Path trace(String arena, String controller, double seconds) throws Exception {
        Path t = dir.resolve(arena + ".trace");
        Simulation.builder().arena(arena).controller(controller).seed(7).seconds(seconds).trace(t).sampleMillis(50).run();
        return t;
    }

    /** The robot lines of a trace at a time, as written. */
    private static List<String[]> linesAt(Path trace, String time) throws Exception {
        List<String[]> out = new ArrayList<>();
        for (String l : Files.readAllLines(trace)) {
            if (l.startsWith(time + " ") && !l.contains(" cap ")) {
                out.add(l.split(" "));
            }
        }
        return out;
    }

    @Test
    void aTraceReplaysEverySampleAsWritten() throws Exception {
        Path t = trace("lab", "Braitenberg", 20);
        Replay r = ReplayFiles.open(t);
        assertEquals(Replay.Kind.TRACE, r.kind());
        assertEquals("lab", r.arena().name());
        assertEquals(401, r.samples(), "0 to 20 s every 50 ms");
        assertEquals(20.0, r.endSeconds(), 1e-9);
        for (String time : new String[] {"0.000", "7.350", "20.000"}) {
            String[] f = linesAt(t, time).get(0);
            Snapshot s = r.at(Double.parseDouble(time) + 0.02); // between samples: the one before
            RobotView v = s.robots().get(0);
            assertEquals(Double.parseDouble(f[2]), v.x(), 1e-3, "x at " + time);
            assertEquals(Double.parseDouble(f[3]), v.y(), 1e-3, "y at " + time);
            assertEquals(Double.parseDouble(f[4]), v.headingDeg(), 1e-3, "heading at " + time);
            assertEquals(Integer.parseInt(f[7]), v.encoderLeft());
            for (int i = 0; i < 8; i++) {
                assertEquals(Integer.parseInt(f[10 + i]), v.proximity(i), "prox" + i + " at " + time);
                assertEquals(Integer.parseInt(f[18 + i]), v.light(i), "light" + i + " at " + time);
            }
        }
        float[] trail = r.trail(0, 1.0);
        assertEquals(2 * 21, trail.length, "the trail holds the samples up to the time shown");
    }

    @Test
    void capsAreWhereTheTraceLastPutThem() throws Exception {
        Path t = trace("two-rooms", "CapGatherer", 120);
        Replay r = ReplayFiles.open(t);
        int caps = ArenaFormat.loadBundled("two-rooms").caps().size();
        assertEquals(caps, r.at(0).caps().size());
        String last = null;
        for (String l : Files.readAllLines(t)) {
            if (l.contains(" cap 0 ")) {
                last = l;
            }
        }
        String[] f = last.split(" ");
        CapView c = r.at(120).caps().get(0);
        assertEquals(Double.parseDouble(f[3]), c.x(), 1e-3);
        assertEquals(Double.parseDouble(f[4]), c.y(), 1e-3);
        assertEquals(Integer.parseInt(f[5]), c.heldBy());
    }

    @Test
    void aRecordingFolderReplaysWithItsOwnArena() throws Exception {
        Path t = trace("maze", "WallFollower", 5);
        Path rec = Files.createDirectories(dir.resolve("rec"));
        ArenaFormat.save(ArenaFormat.loadBundled("maze"), rec.resolve("start.arena"));
        Files.copy(t, rec.resolve("run.trace"));
        Replay r = ReplayFiles.open(rec);
        assertEquals(Replay.Kind.RECORDING, r.kind());
        assertEquals("maze", r.arena().name());
        assertEquals(101, r.samples());
        Files.delete(rec.resolve("run.trace"));
        InputFileException e = assertThrows(InputFileException.class, () -> ReplayFiles.open(rec));
        assertTrue(e.getMessage().contains("run.trace is missing"), e.getMessage());
    }

    @Test
    void aTraceCutMidLineIsReadUpToItsLastWholeLine() throws Exception {
        Path t = trace("lab", "Braitenberg", 10);
        String text = Files.readString(t);
        Path cut = dir.resolve("cut.trace");
        Files.writeString(cut, text.substring(0, text.indexOf("\n", text.indexOf("\n6.000 ") + 1) + 20));
        Replay r = ReplayFiles.open(cut);
        assertEquals(6.0, r.endSeconds(), 1e-9);
        assertTrue(r.notes().stream().anyMatch(n -> n.contains("middle of a line")), r.notes().toString());
    }

    @Test
    void aBrokenTraceNamesTheLine() throws Exception {
        Path t = trace("lab", "Braitenberg", 1);
        List<String> lines = new ArrayList<>(Files.readAllLines(t));
        lines.set(12, lines.get(12).replace("NONE", "SIDEWAYS"));
        Path bad = dir.resolve("bad.trace");
        Files.write(bad, lines);
        InputFileException e = assertThrows(InputFileException.class, () -> ReplayFiles.open(bad));
        assertTrue(e.getMessage().startsWith(bad + ":13: "), e.getMessage());
        Path foreign = dir.resolve("notes.txt");
        Files.writeString(foreign, "shopping list\n");
        e = assertThrows(InputFileException.class, () -> ReplayFiles.open(foreign));
        assertTrue(e.getMessage().startsWith(foreign + ":1: "), e.getMessage());
    }

    @Test
    void aRealRobotsRecordingIsDeadReckonedFromItsEncoders() throws Exception {
        StringBuilder b = new StringBuilder("# khepera-link recording v1, started 2026-11-23T08:00:00Z\n"
                + "# controller WallFollower on /dev/ttyUSB0 at 38400 baud\n# t_s prox0..prox7 light0..light7 posL posR speedL speedR\n");
        // 1 s straight (1250 pulses = 100 mm), then a quarter turn on the spot (53 mm base: pi/2 * 26.5 / 0.08 pulses).
        int turn = (int) StrictMath.round(StrictMath.PI / 2 * 26.5 / 0.08);
        for (int k = 0; k <= 10; k++) {
            b.append(line(k * 0.1, k * 125, k * 125, 5));
        }
        b.append(line(1.5, 1250 - turn, 1250 + turn, 0));
        Path rec = dir.resolve("robot.txt");
        Files.writeString(rec, b.toString());
        Replay r = ReplayFiles.open(rec);
        assertEquals(Replay.Kind.LINK_RECORDING, r.kind());
        RobotView straight = r.at(1.0).robots().get(0);
        assertEquals(609.6, straight.x(), 1e-3);
        assertEquals(609.6 + 100, straight.y(), 1e-3, "100 mm ahead (heading 90 degrees)");
        assertEquals(1250, straight.encoderLeft());
        assertEquals(5, straight.speedLeft());
        RobotView turned = r.at(2).robots().get(0);
        assertEquals(180, turned.headingDeg(), 0.2, "a quarter turn to the left");
        assertEquals(straight.x(), turned.x(), 1e-6);
        Files.writeString(rec, b + "1.6 1 2 3\n");
        InputFileException e = assertThrows(InputFileException.class, () -> ReplayFiles.open(rec));
        assertTrue(e.getMessage().startsWith(rec + ":16: "), e.getMessage());
    }

    /** compare's page dead-reckons both runs with the robot's own wheels: an e-puck's 0.1288 mm steps, not 0.08 mm. */
    @Test
    void compareSideBySideUsesTheRobotsWheels() {
        StringBuilder b = new StringBuilder("# khepera-link recording v2, started 2026-11-23T08:00:00Z\n");
        for (int k = 0; k <= 10; k++) {
            b.append(line(k * 0.1, k * 100, k * 100, 200));
        }
        // Then a quarter turn on the spot on the e-puck's 53 mm wheel base.
        int turn = (int) StrictMath.round(StrictMath.PI / 2 * 26.5 / 0.1288);
        b.append(line(1.5, 1000 - turn, 1000 + turn, 0));
        org.kheperasim.sim.engine.robot.RobotType.Drive d =
                org.kheperasim.sim.engine.robot.RobotTypes.named("epuck").drive();
        org.kheperasim.sim.arena.Arena arena = org.kheperasim.sim.arena.ArenaFormat.resolve("maze");
        Replay r = ReplayFiles.sideBySide(b.toString(), b.toString(), "epuck.rec", arena,
                new org.kheperasim.sim.arena.Pose(300, 300, 0), d.mmPerPulse(), d.wheelBaseMm());
        for (int robot = 0; robot < 2; robot++) {
            RobotView straight = r.at(1.0).robots().get(robot);
            assertEquals(300 + 1000 * 0.1288, straight.x(), 1e-3, "1000 steps of 0.1288 mm ahead");
            assertEquals(90, r.at(2).robots().get(robot).headingDeg(), 0.3, "a quarter turn on 53 mm");
        }
    }

    private static String line(double t, int l, int r, int speed) {
        return String.format(java.util.Locale.ROOT, "%.4f 1 2 3 4 5 6 7 8 500 500 500 500 500 500 500 500 %d %d %d %d%n",
                t, l, r, speed, speed);
    }
}
