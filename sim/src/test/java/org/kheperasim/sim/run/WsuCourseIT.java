package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.cap;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.light;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.wsu.WsuWorldWriter;
import org.kheperasim.sim.host.ConsoleLine;

import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * Course material written for the WSU simulator, as an instructor brings it: controllers in the
 * default package with a helper class in a package folder beside them, compiled by javac against
 * the runnable jar ({@code target/khepera-sim.jar}, so this runs after {@code package}), and a
 * world file in the WSU format. Each controller runs from that world, twice with random real-time
 * delays at every hand-over, and gives the same trace both times.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuCourseIT {
    private static final List<String> SOURCES = List.of("WsuAvoider", "WsuCounterTurn", "WsuHelped", "WsuSensorThread",
            "WsuSlow", "WsuGripper", "util/Smoother");

    @TempDir
    static Path dir;
    static Path classes;
    static Path world;

    @BeforeAll
    static void compileAgainstTheJarAndWriteAWorld() throws IOException {
        Path jar = Path.of("target", "khepera-sim.jar");
        assertTrue(Files.isRegularFile(jar), "the runnable jar is built before the integration tests: " + jar.toAbsolutePath());
        Path src = dir.resolve("controllers");
        classes = dir.resolve("classes");
        Files.createDirectories(src.resolve("util"));
        Files.createDirectories(classes);
        List<String> args = new ArrayList<>(List.of("-cp", jar.toString(), "-d", classes.toString(), "--release", "17",
                "-proc:none"));
        for (String s : SOURCES) {
            Path file = src.resolve(s + ".java");
            try (InputStream in = WsuCourseIT.class.getResourceAsStream("/wsu-course/" + s + ".java")) {
                Files.write(file, in.readAllBytes());
            }
            args.add(file.toString());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])),
                "the WSU controllers compile against the runnable jar alone");
        assertTrue(Files.isRegularFile(classes.resolve("util/Smoother.class")), "the helper class is in its package folder");
        // The robot starts at (263, 263) px facing east (the original's default); a cap 100 mm ahead of
        // it, walls of both orientations, a lamp.
        world = dir.resolve("course.map");
        Files.write(world, WsuWorldWriter.world(List.of(cap(1, 300, 259), vertical(2, 400, 150), vertical(3, 400, 200),
                horizontal(4, 100, 120), horizontal(5, 150, 120), light(6, 60, 400))));
    }

    private record Run(RunResult result, String trace, List<String> console) {
        String text() {
            return String.join("\n", console);
        }
    }

    private static Run run(String controller, double seconds) {
        return run(controller, seconds, 3);
    }

    private static Run run(String controller, double seconds, long seed) {
        StringWriter trace = new StringWriter();
        List<String> console = new CopyOnWriteArrayList<>();
        RunResult r = Simulation.builder().arena(world.toString()).classpath(List.of(classes)).controller(controller)
                .seed(seed).seconds(seconds).trace(trace).hostOptions(HostOptions.defaults().withJitter(200))
                .console((ConsoleLine l) -> console.add(l.text())).run();
        return new Run(r, trace.toString(), console);
    }

    /** Runs twice with jitter; the traces are identical; returns the first run. */
    private static Run deterministic(String controller, double seconds) {
        return deterministic(controller, seconds, 3);
    }

    private static Run deterministic(String controller, double seconds, long seed) {
        Run first = run(controller, seconds, seed);
        Run second = run(controller, seconds, seed);
        assertEquals(first.trace, second.trace, controller + ": the same trace twice");
        assertEquals(first.console, second.console, controller + ": the same console twice");
        assertFalse(first.trace.isEmpty());
        return first;
    }

    @Test
    void theReactiveAvoiderRoamsTheWorld() {
        // Seed 1. With the robot's 20 ms scans, seed 3 wedges the avoider in a corner after 737 mm (turning right for
        // its front sensors, left for sensor 4, in turn): a reactive avoider can; seeds 1..10 but 3 drive 2.05-2.23 m.
        Run r = deterministic("WsuAvoider", 60, 1);
        assertEquals(ControllerStatus.STOPPED, r.result.first().status(), r.text());
        assertTrue(r.result.first().distanceMm() > 1000, "it drives: " + r.result.first());
        assertTrue(r.trace.contains("course.map") || r.trace.contains("course"), "the trace names the world");
    }

    @Test
    void theWheelCounterBusyWaitTurnsAQuarterAndStops() {
        Run r = deterministic("WsuCounterTurn", 30);
        assertEquals(ControllerStatus.FINISHED, r.result.first().status(), r.text());
        assertTrue(r.text().contains("turned at "), "its System.out line reached the console: " + r.text());
        // It faced east (0 deg); a quarter turn to the left.
        double heading = r.result.first().headingDeg();
        assertTrue(Math.abs(Math.abs(heading) - 90) < 10, "turned by about 90 deg: " + r.result.first());
    }

    @Test
    void aControllerWithAPackagedHelperClassRuns() {
        Run r = deterministic("WsuHelped", 60);
        assertEquals(ControllerStatus.STOPPED, r.result.first().status(), r.text());
        assertTrue(r.result.first().distanceMm() > 1000, "it drives: " + r.result.first());
    }

    @Test
    void aHelperThreadStartedInTheConstructorRunsInTheLockstep() {
        Run r = deterministic("WsuSensorThread", 60);
        assertEquals(ControllerStatus.STOPPED, r.result.first().status(), r.text());
        // The manager reads every 30 ms of simulated time (plus its API calls): its 100th read
        // falls just after 2.97 s, whatever the machine's speed.
        assertTrue(r.text().matches("(?s).*100 reads at 629[7-9][0-9].*"), r.text());
        assertFalse(r.text().contains("left behind"), r.text());
        assertTrue(r.result.first().distanceMm() > 300, "it drives: " + r.result.first());
    }

    @Test
    void setWaitTimeInTheConstructorAndOutOfRangeSpeeds() {
        Run r = deterministic("WsuSlow", 10);
        assertEquals(ControllerStatus.FINISHED, r.result.first().status(), r.text());
        // The original's quirk, kept: the simulator sets the pause to 20 ms after construction, so the
        // constructor's setWaitTime(100) has no effect: fifty pauses of 20 ms before the 51st doWork.
        assertTrue(r.text().matches("(?s).*step 51 at 6100[0-9].*"), r.text());
        // Speed 12 was ignored: only the right wheel turned (4 units), so the robot turned left on the spot
        // around its left wheel: about 1 s x 32 mm/s / 2 of travel at its centre.
        RunResult.RobotResult robot = r.result.first();
        assertTrue(robot.distanceMm() > 5 && robot.distanceMm() < 25, "half a wheel's travel: " + robot);
        assertTrue(robot.headingDeg() > 20, "turned left (counterclockwise): " + robot);
    }

    @Test
    void theGripperUserPicksUpTheCapAhead() {
        Run r = deterministic("WsuGripper", 60);
        assertEquals(ControllerStatus.FINISHED, r.result.first().status(), r.text());
        assertTrue(r.text().contains("holding true arm up true gripper closed true"), r.text());
    }
}
