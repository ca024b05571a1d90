package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * Controllers written for the WSU Khepera Simulator (default package, {@code extends RobotController})
 * compiled from source, found by robot-link's own controller loading, and run on the fake robot over a
 * socat pty pair. Every run ends with {@code D,0,0} the last line the robot received.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy.
 */
@Tag("timing")
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuControllerPtyTest {
    @TempDir
    Path dir;

    private final List<String> console = Collections.synchronizedList(new ArrayList<>());
    private final Consumer<String> out = console::add;

    /** A reactive avoider as students wrote them for the original; it also asks for a speed out of range. */
    private static final String AVOIDER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Avoider extends RobotController {
                public Avoider() { }

                public void doWork() throws Exception {
                    setMotorSpeeds(12, 12);              // out of -9..9: ignored, as in the original
                    if (getDistanceValue(2) > 600 || getDistanceValue(3) > 600) {
                        setMotorSpeeds(3, -3);
                    } else {
                        setMotorSpeeds(5, 5);
                    }
                    sleep(30);
                }

                public void close() throws Exception {
                    setMotorSpeeds(0, 0);
                }
            }
            """;

    private static final String CRASHER = """
            import edu.wsu.KheperaSimulator.*;

            public class Crasher extends RobotController {
                private int steps;
                public Crasher() { }

                public void doWork() throws Exception {
                    setMotorSpeeds(6, 6);
                    if (++steps == 5) {
                        throw new java.io.IOException("student bug");
                    }
                }

                public void close() throws Exception { }
            }
            """;

    private static final String GRABBER = """
            import edu.wsu.KheperaSimulator.*;

            public class Grabber extends RobotController {
                public Grabber() { }

                public void doWork() throws Exception {
                    setArmState(KSGripperStates.ARM_DOWN);
                    sleep(100);
                    setGripperState(KSGripperStates.GRIP_CLOSED);
                    sleep(100);
                    setFinished(true);
                }

                public void close() throws Exception { }
            }
            """;

    private Path compile(Map<String, String> sources) throws Exception {
        Path src = Files.createDirectories(dir.resolve("src"));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "-d", classes.toString()));
        for (Map.Entry<String, String> e : sources.entrySet()) {
            Path file = src.resolve(e.getKey() + ".java");
            Files.writeString(file, e.getValue());
            args.add(file.toString());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])));
        return classes;
    }

    private RobotRun.Result run(FakeRobotOnPty fake, Class<?> controller, RobotSettings settings, long millis,
            RobotScript script) throws Exception {
        SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
        // No fault is injected: a reply may take 1 s (150 ms timed out answered commands on a machine at load 30).
        try (Session s = new Session(link, LinkTiming.atBaud(38400), new Session.Options(1000, 3, 100, 2000))) {
            s.open();
            RobotRun run = new RobotRun(new RobotBackend(s, settings, out), controller, out);
            return RobotScript.play(script, fake.robot(), run, millis);
        }
    }

    private static void assertStoppedLast(FakeKhepera robot) {
        List<String> got = robot.received();
        assertEquals("D,0,0", robot.lastReceived(), "the last line the robot received; all: "
                + got.subList(Math.max(0, got.size() - 12), got.size()));
    }

    @Test
    void aReactiveWsuAvoiderDrivesTheRobotUnchanged() throws Exception {
        Path classes = compile(Map.of("Avoider", AVOIDER));
        Class<?> avoider = new ControllerLoader(List.of(classes)).load("Avoider");
        assertEquals("Avoider", avoider.getName());
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            RobotRun.Result r = run(fake, avoider, RobotSettings.defaults(), 30_000, (rb, run) -> {
                RobotScript.awaitReceived(rb, "D,5,5", 0);    // open floor: ahead at (5, 5)
                rb.setProximity(0, 0, 800, 800, 0, 0, 0, 0);
                RobotScript.awaitReceived(rb, "D,3,-3", 0);   // wall ahead: turn on the spot (3, -3)
                rb.setProximity(0, 0, 0, 0, 0, 0, 0, 0);      // clear again: ahead
                RobotScript.awaitReceived(rb, "D,5,5", 1);
                run.requestStop("the moves were seen");
            });
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
            List<String> d = robot.received().stream().filter(l -> l.startsWith("D")).toList();
            int ahead = d.indexOf("D,5,5");
            int turn = d.indexOf("D,3,-3");
            int again = d.subList(Math.max(turn, 0), d.size()).indexOf("D,5,5");
            assertTrue(ahead >= 0 && ahead < turn && again > 0, "ahead, turn, ahead again: " + d);
            assertFalse(d.stream().anyMatch(l -> l.contains("12")), "out-of-range speeds are never sent: " + d);
            assertTrue(r.stopAcknowledged());
            assertStoppedLast(robot);
        }
    }

    @Test
    void aWsuControllerThatThrowsIsReportedAndTheRobotStopped() throws Exception {
        Path classes = compile(Map.of("Crasher", CRASHER));
        Class<?> crasher = new ControllerLoader(List.of(classes)).load("Crasher");
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, crasher, RobotSettings.defaults(), 10_000, RobotScript.NOTHING);
            assertEquals(RobotRun.End.FAILED, r.end());
            assertTrue(r.detail().contains("java.io.IOException: student bug"), r.detail());
            assertTrue(fake.robot().received().contains("D,6,6"));
            assertStoppedLast(fake.robot());
        }
    }

    @Test
    void wsuGripperStatesBecomeTheTurretCommandsOfTheOriginalsRemoteProgram() throws Exception {
        Path classes = compile(Map.of("Grabber", GRABBER));
        Class<?> grabber = new ControllerLoader(List.of(classes)).load("Grabber");
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, grabber, RobotSettings.defaults().withGripper(true, false), 10_000,
                    RobotScript.NOTHING);
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            List<String> got = fake.robot().received();
            assertTrue(got.contains("T,1,E,249") && got.contains("T,1,D,1"), "arm down, fingers closed: " + got);
            assertStoppedLast(fake.robot());
        }
    }
}
