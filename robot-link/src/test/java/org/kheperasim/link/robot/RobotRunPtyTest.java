package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.testcontrollers.Fast;
import org.kheperasim.link.testcontrollers.Forward;
import org.kheperasim.link.testcontrollers.Returner;
import org.kheperasim.link.testcontrollers.Thrower;
import org.kheperasim.link.timing.LinkTiming;

/**
 * A controller runs on the fake robot over a socat pty pair (robot-link's side through jSerialComm).
 * Every test ends by checking that the last line the robot received is {@code D,0,0}.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotRunPtyTest {
    @TempDir
    Path dir;

    private final List<String> console = Collections.synchronizedList(new ArrayList<>());
    private final Consumer<String> out = line -> console.add(line);

    private RobotRun.Result run(FakeRobotOnPty fake, Class<?> controller, RobotSettings settings, long millis,
            Consumer<FakeKhepera> during) throws Exception {
        SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
        try (Session s = new Session(link, LinkTiming.atBaud(38400), new Session.Options(150, 3, 100, 2000))) {
            s.open();
            RobotBackend backend = new RobotBackend(s, settings, out);
            RobotRun run = new RobotRun(backend, controller, out);
            Thread faults = new Thread(() -> {
                try {
                    Thread.sleep(300);
                } catch (InterruptedException e) {
                    return;
                }
                during.accept(fake.robot());
            });
            faults.setDaemon(true);
            faults.start();
            RobotRun.Result r = run.run(millis);
            faults.join(5000);
            return r;
        }
    }

    private static void assertStoppedLast(FakeKhepera robot) {
        assertEquals("D,0,0", robot.lastReceived(), "the last line the robot received; all: " + tail(robot.received()));
    }

    private static List<String> tail(List<String> l) {
        return l.subList(Math.max(0, l.size() - 12), l.size());
    }

    @Test
    void wallFollowerRunsUnchangedAndItsMotorCommandsArrive() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            Class<?> wf = new ControllerLoader(List.of()).load("WallFollower");
            assertEquals("org.kheperasim.controllers.WallFollower", wf.getName());
            RobotRun.Result r = run(fake, wf, RobotSettings.defaults(), 3000, rb -> {
                try {
                    Thread.sleep(300);          // findwall(): driving ahead at (3, 3)
                    rb.setProximity(0, 0, 700, 0, 0, 0, 0, 0);
                    Thread.sleep(500);          // wall ahead: turn on the spot (2, -2)
                    rb.setProximity(700, 0, 0, 0, 0, 0, 0, 0);
                    Thread.sleep(500);          // wall on the left only: follow it (3, -1)
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            assertEquals(RobotRun.End.TIME_UP, r.end(), r.detail());
            List<String> d = robot.received().stream().filter(l -> l.startsWith("D")).toList();
            int ahead = d.indexOf("D,3,3");
            int turn = d.indexOf("D,2,-2");
            int follow = d.indexOf("D,3,-1");
            assertTrue(ahead >= 0 && ahead < turn && turn < follow, "the Appendix's moves in order: " + d);
            assertTrue(r.pollRateHz() > 5, "polled: " + r.pollRateHz());
            assertTrue(r.stopAcknowledged());
            assertStoppedLast(robot);
        }
    }

    @Test
    void aStepControllerRunsOnTheRealRobotSteppedEveryPeriodAndEndsWithTheRobotStopped() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            Class<?> step = new ControllerLoader(List.of()).load("StepBraitenberg");
            RobotRun.Result r = run(fake, step, RobotSettings.defaults(), 2000, rb -> {
                try {
                    Thread.sleep(700);          // nothing in sight: cruising at (6, 6)
                    rb.setProximity(0, 0, 700, 0, 0, 0, 0, 0);
                    Thread.sleep(700);          // something ahead on the left: a later step spins right (4, -4)
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            assertEquals(RobotRun.End.TIME_UP, r.end(), r.detail());
            List<String> d = robot.received().stream().filter(l -> l.startsWith("D")).toList();
            int cruise = d.indexOf("D,6,6");
            int spin = d.indexOf("D,4,-4");
            assertTrue(cruise >= 0 && cruise < spin, "the steps' speeds reached the robot, in order: " + d);
            assertTrue(r.pollRateHz() > 5, "the sensors were polled for the steps: " + r.pollRateHz());
            assertStoppedLast(robot);
        }
    }

    @Test
    void garbageDroppedLateAndBannerFaultsAreSurvived() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 2500, rb -> {
                try {
                    rb.noiseBeforeNextReply("\u0000\u00ffgarbage\r\n");
                    Thread.sleep(200);
                    rb.dropReplies(1);
                    Thread.sleep(300);
                    rb.lateReply(250);
                    Thread.sleep(500);
                    rb.resetAtNextCommand();
                    Thread.sleep(500);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            assertEquals(RobotRun.End.TIME_UP, r.end(), r.detail());
            assertTrue(r.stats().retries() >= 3, "the faults cost retries: " + r.stats());
            int[] speeds = robot.speeds();
            assertEquals(0, speeds[0]);
            assertStoppedLast(robot);
        }
    }

    @Test
    void aResetRobotGetsItsSpeedsAgain() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            int[] seen = new int[2];
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 1500, rb -> {
                try {
                    Thread.sleep(200);
                    rb.resetAtNextCommand();
                    Thread.sleep(600);
                    int[] s = rb.speeds();
                    seen[0] = s[0];
                    seen[1] = s[1];
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            assertEquals(RobotRun.End.TIME_UP, r.end(), r.detail());
            assertEquals(5, seen[0], "after a reset (which stops the wheels) the controller's speeds are sent again");
            assertStoppedLast(robot);
        }
    }

    @Test
    void aRobotThatFallsSilentIsReportedAndToldToStop() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            long start = System.nanoTime();
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 20_000, rb -> rb.setSilent(true));
            assertEquals(RobotRun.End.LINK_LOST, r.end());
            assertTrue(r.detail().contains("no reply to"), r.detail());
            assertFalse(r.stopAcknowledged());
            assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(10), "noticed within seconds");
            assertStoppedLast(robot);
        }
    }

    @Test
    void theFarEndVanishingEndsTheRunWithAClearReport() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 20_000, rb -> {
                try {
                    fake.pty().kill();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            assertEquals(RobotRun.End.LINK_LOST, r.end());
            assertTrue(r.detail().contains("has gone"), r.detail());
            // The pty is gone: nothing can reach the robot any more; what it last heard while there was a D.
            assertTrue(robot.received().contains("D,5,5"));
        }
    }

    @Test
    void aControllerThatThrowsStopsTheRobot() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, Thrower.class, RobotSettings.defaults(), 10_000, rb -> { });
            assertEquals(RobotRun.End.FAILED, r.end());
            assertTrue(r.detail().contains("student bug"), r.detail());
            assertTrue(fake.robot().received().contains("D,6,6"));
            assertStoppedLast(fake.robot());
        }
    }

    @Test
    void aControllerThatReturnsWithWheelsTurningStopsTheRobot() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, Returner.class, RobotSettings.defaults(), 10_000, rb -> { });
            assertEquals(RobotRun.End.FINISHED, r.end());
            assertTrue(fake.robot().received().contains("D,7,7"));
            assertTrue(console.stream().anyMatch(l -> l.contains("Returner: driving at 7")), console.toString());
            assertStoppedLast(fake.robot());
        }
    }

    @Test
    void aStopRequestStopsTheRobot() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
            try (Session s = new Session(link, LinkTiming.atBaud(38400), Session.Options.defaults())) {
                s.open();
                RobotRun run = new RobotRun(new RobotBackend(s, RobotSettings.defaults(), out), Forward.class, out);
                Thread stopper = new Thread(() -> {
                    try {
                        Thread.sleep(500);
                    } catch (InterruptedException e) {
                        return;
                    }
                    run.requestStop("the user pressed stop");
                });
                stopper.start();
                RobotRun.Result r = run.run(0);
                assertEquals(RobotRun.End.STOPPED, r.end());
                assertEquals("the user pressed stop", r.detail());
            }
            assertStoppedLast(fake.robot());
        }
    }

    @Test
    void speedsAreClampedAndTheGripperIsParkedOnStop() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotSettings settings = RobotSettings.defaults().withMaxSpeed(12).withGripper(true, true);
            RobotRun.Result r = run(fake, Fast.class, settings, 800, rb -> { });
            assertEquals(RobotRun.End.TIME_UP, r.end(), r.detail());
            List<String> got = fake.robot().received();
            assertTrue(got.contains("D,12,-12"), "clamped: " + tail(got));
            assertFalse(got.stream().anyMatch(l -> l.startsWith("D,100")));
            assertTrue(got.contains("T,1,E,249") && got.contains("T,1,D,1"), "gripper commands arrive");
            assertTrue(got.contains("T,1,G") && got.contains("T,1,F"), "gripper state is polled");
            assertTrue(console.stream().anyMatch(l -> l.contains("limited to ±12")), console.toString());
            List<String> end = got.subList(got.size() - 4, got.size());
            assertEquals(List.of("D,0,0", "T,1,D,0", "T,1,E,180", "D,0,0"), end);
        }
    }
}
