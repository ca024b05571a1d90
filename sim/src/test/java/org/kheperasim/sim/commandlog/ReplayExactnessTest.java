package org.kheperasim.sim.commandlog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * The open-loop replay of a run's command log gives the run's own trace, byte for byte: every bundled
 * arena with every bundled controller (60 or 150 s, see {@link #SECONDS}), and arenas of several robots (thread and step controllers,
 * different controllers side by side, caps pushed among robots), controllers that read the vision
 * turret (the student API, a step controller, WSU's readLvtImage), three mixed robots over several
 * seeds, what the wall clock decides (a 2 ms hang timeout with real-time jitter in the hand-offs, a
 * stop by the wall clock). This is what lets a grader score the replay instead of trusting what the
 * run says it scored. The cases tagged {@code timing} run again in {@code .ci/run}'s busy pass.
 */
@Timeout(value = 900, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ReplayExactnessTest {
    /**
     * A bundled run's length: 60 s, where by 60 s the run already shows all it shows by 150 s (the kinds
     * of command-log line, a collision, the gripper, caps in each region; measured for seed 42), and
     * 150 s for the three runs where it does not (a wall follower's first collision in lab and in
     * two-rooms, the cap gatherer's first deliveries).
     */
    private static final double SECONDS = 60;
    private static final double LONG_SECONDS = 150;
    private static final java.util.Set<String> LONG = java.util.Set.of("lab WallFollower", "two-rooms WallFollower",
            "two-rooms CapGatherer");
    private static final long SAMPLE_MS = 20;

    static Stream<Arguments> bundled() {
        List<Arguments> out = new ArrayList<>();
        for (String arena : ArenaFormat.bundledNames()) {
            for (String controller : ControllerCatalog.bundled()) {
                out.add(Arguments.of(arena, controller));
            }
        }
        return out.stream();
    }

    @ParameterizedTest(name = "{0} with {1}")
    @MethodSource("bundled")
    void theReplayOfEveryBundledRunIsTheRun(String arena, String controller) throws IOException {
        double seconds = LONG.contains(arena + " " + controller) ? LONG_SECONDS : SECONDS;
        Simulation.Builder run = Simulation.builder().arena(arena).controller(controller).seed(42).seconds(seconds);
        assertReplayIsTheRun(run);
    }

    /**
     * The wall followers' crowd runs 30 s, not 60: it is the slowest case by far (its robots cluster;
     * 6.7 s for 60 s, 2.2 s for 30 s), and by 30 s twelve of its robots have collided and its caps been
     * pushed (284 cap positions in the trace against 326 by 60 s).
     */
    static Stream<Arguments> crowds() {
        return Stream.of(Arguments.of("Braitenberg", false, 60), Arguments.of("StepBraitenberg", true, 60),
                Arguments.of("Aggregation", true, 60), Arguments.of("WallFollower", true, 30));
    }

    @ParameterizedTest(name = "sixteen robots with {0}, caps {1}, {2} s")
    @MethodSource("crowds")
    void theReplayOfACrowdIsTheRun(String controller, boolean caps, int seconds) throws IOException {
        Simulation.Builder run = Simulation.builder().arena(crowd(caps)).controller(controller).seed(7).seconds(seconds);
        assertReplayIsTheRun(run);
    }

    @Test
    void theReplayOfRobotsWithControllersAndSettingsOfTheirOwnIsTheRun() throws IOException {
        Simulation.Builder run = Simulation.builder().arena(org.kheperasim.testfixtures.Arenas.THREE).controller("Braitenberg")
                .robot(1, "WallFollower", null).robot(2, "StepBraitenberg", Settings.defaults().with("motor.left.calibration", "0.9"))
                .seed(21).seconds(120);
        assertReplayIsTheRun(run);
    }

    static Stream<Arguments> turretReaders() {
        List<Arguments> out = new ArrayList<>();
        for (String controller : List.of("VisionSteerer", "VisionStepper", "WsuTurretReader")) {
            for (String arena : List.of("two-rooms", "beacon-maze", "lab")) {
                out.add(Arguments.of(controller, arena));
            }
        }
        return out.stream();
    }

    /** Controllers that read the K213 turret (the student API, a step controller, WSU KSuite 1.1.2's readLvtImage). */
    @ParameterizedTest(name = "{0} in {1}")
    @MethodSource("turretReaders")
    @Tag("timing")
    void theReplayOfARunThatReadsTheVisionTurretIsTheRun(String controller, String arena) throws IOException {
        Simulation.Builder run = Simulation.builder().arena(arena).controller("org.kheperasim.testcontrollers." + controller)
                .seed(5).seconds(60);
        assertTrue(assertReplayIsTheRun(run).trace.contains("\n# vision "), "the run's trace shows the turret's images");
    }

    /** Two thread controllers and a step controller with its own calibration, over several seeds. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 2, 3, 4})
    @Tag("timing")
    void theReplayOfMixedRobotsIsTheRunOverSeveralSeeds(long seed) throws IOException {
        assertReplayIsTheRun(mixed("Braitenberg", seed, 90, HostOptions.defaults()));
    }

    /**
     * The real-time paths forced: a hang timeout of 2 ms and random real-time delays of up to 3 ms
     * inside the simulator's hand-offs, beside a controller that thinks for milliseconds between robot
     * calls. The watchdog then takes controllers off the run where the wall clock decides; whatever it
     * decides, the log records it and its replay is the run.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    @Tag("timing")
    void whatTheWallClockDecidesIsInTheLogAndTheReplayIsTheRun(long seed) throws IOException {
        HostOptions hurried = HostOptions.defaults().withHangTimeout(2_000_000L).withJitter(3000);
        Recorded r = assertReplayIsTheRun(mixed("org.kheperasim.testcontrollers.Ponderer", seed, 20, hurried));
        assertTrue(r.result.robots().stream().anyMatch(b -> b.status() == ControllerStatus.HUNG),
                "the watchdog took a controller off the run (the real-time path was taken): " + r.result.robots());
    }

    /** A run stopped where the wall clock says (as a signal stops it): the log says where, and the replay ends there too. */
    @Test
    @Tag("timing")
    void aRunStoppedByTheWallClockIsReplayedToWhereItStopped() throws IOException {
        long[] asked = {0};
        Simulation.Builder run = mixed("Braitenberg", 9, 600, HostOptions.defaults()).stopWhen(() -> ++asked[0] > 40);
        Recorded r = assertReplayIsTheRun(run);
        assertTrue(r.result.simulatedSeconds() < 600, "it was stopped early: " + r.result.simulatedSeconds());
        assertTrue(r.log.contains("\nq "), "the log says where");
    }

    private static Simulation.Builder mixed(String first, long seed, double seconds, HostOptions options) {
        return Simulation.builder().arena(org.kheperasim.testfixtures.Arenas.THREE).controller(first)
                .robot(1, "WallFollower", null).robot(2, "StepBraitenberg", Settings.defaults().with("motor.left.calibration", "0.9"))
                .seed(seed).seconds(seconds).hostOptions(options);
    }

    @Test
    void aLogOfAnotherRunIsRefused() throws IOException {
        Simulation.Builder run = Simulation.builder().arena("lab").controller("Braitenberg").seed(3).seconds(5);
        Recorded r = record(run);
        OpenLoopReplay.Run other = new OpenLoopReplay.Run(run.arena(), 4, nanos(run.seconds()), SAMPLE_MS, run.robotSettings());
        ReplayMismatchException e = assertThrows(ReplayMismatchException.class,
                () -> OpenLoopReplay.replay(other, reader(r.log), new StringWriter()));
        assertTrue(e.getMessage().contains("seed 3"), e.getMessage());
        String torn = r.log.substring(0, r.log.length() / 2);
        OpenLoopReplay.Run same = new OpenLoopReplay.Run(run.arena(), 3, nanos(run.seconds()), SAMPLE_MS, run.robotSettings());
        RuntimeException t = assertThrows(RuntimeException.class, () -> OpenLoopReplay.replay(same, reader(torn), new StringWriter()));
        assertTrue(t.getMessage().contains("ends") || t.getMessage().contains("torn"), t.getMessage());
    }

    private record Recorded(String log, String trace, RunResult result) {
    }

    static Recorded assertReplayIsTheRun(Simulation.Builder run) throws IOException {
        Recorded r = record(run);
        StringWriter replayed = new StringWriter();
        OpenLoopReplay.Outcome o = OpenLoopReplay.replay(new OpenLoopReplay.Run(run.arena(), run.seed(), nanos(run.seconds()),
                SAMPLE_MS, run.robotSettings()), reader(r.log), replayed);
        assertEquals(r.trace, replayed.toString(), "the replay's trace is the run's");
        assertEquals(r.result.traceSha256(), o.result().traceSha256());
        assertEquals(r.result.simulatedSeconds(), o.result().simulatedSeconds());
        assertEquals(r.result.capsInRegions(), o.result().capsInRegions());
        for (int i = 0; i < r.result.robots().size(); i++) {
            RunResult.RobotResult a = r.result.robots().get(i);
            RunResult.RobotResult b = o.result().robots().get(i);
            assertEquals(String.format(Locale.ROOT, "%s %s %s %s %d %s %s", a.x(), a.y(), a.headingDeg(), a.distanceMm(),
                    a.collisions(), a.visitedPercent(), a.regionsEntered()),
                    String.format(Locale.ROOT, "%s %s %s %s %d %s %s", b.x(), b.y(), b.headingDeg(), b.distanceMm(),
                    b.collisions(), b.visitedPercent(), b.regionsEntered()), "robot " + i + " ends the same");
        }
        assertEquals("{\"test\": 1}", o.claim());
        return r;
    }

    private static Recorded record(Simulation.Builder run) throws IOException {
        StringWriter log = new StringWriter();
        StringWriter trace = new StringWriter();
        CommandLogWriter writer = new CommandLogWriter(log);
        RunResult result = run.sampleMillis(SAMPLE_MS).trace(trace).record(writer)
                .onStart(s -> writer.start(LogHeader.of(s, nanos(run.seconds()), SAMPLE_MS))).run();
        writer.finish("{\"test\": 1}");
        return new Recorded(log.toString(), trace.toString(), result);
    }

    /** @return the first line where two traces differ, both versions, or "" when they are the same */
    static String firstDifference(String a, String b) {
        String[] x = a.split("\n", -1);
        String[] y = b.split("\n", -1);
        for (int i = 0; i < StrictMath.max(x.length, y.length); i++) {
            String l = i < x.length ? x[i] : "(end)";
            String m = i < y.length ? y[i] : "(end)";
            if (!l.equals(m)) {
                return "line " + (i + 1) + ": run '" + l + "', replay '" + m + "'";
            }
        }
        return "";
    }

    private static CommandLogReader reader(String log) {
        return new CommandLogReader(new BufferedReader(new StringReader(log)));
    }

    private static long nanos(double seconds) {
        return (long) StrictMath.rint(seconds * 1e9);
    }

    /** Sixteen robots on a 170 mm lattice (as SwarmEquivalenceTest's crowd); with caps, three among them. */
    static Arena crowd(boolean caps) {
        StringBuilder text = new StringBuilder("khepera-arena 1\nname crowd\nsize 800 800\n"
                + "wall 0 4 800 4 8\nwall 0 796 800 796 8\nwall 4 0 4 800 8\nwall 796 0 796 800 8\n");
        for (int i = 0; i < 16; i++) {
            double x = 145 + (i % 4) * 170 + ((i * 7) % 5 - 2) * 6;
            double y = 145 + (i / 4) * 170 + ((i * 3) % 5 - 2) * 6;
            text.append(String.format(Locale.ROOT, "robot %.1f %.1f %d%n", x, y, (i * 137) % 360 - 180));
        }
        if (caps) {
            text.append("cap 230 230\ncap 400 485\ncap 570 315\n");
        }
        return ArenaFormat.parse(text.toString(), "crowd");
    }
}
