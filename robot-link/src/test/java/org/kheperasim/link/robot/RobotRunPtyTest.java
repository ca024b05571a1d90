package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.link.robot.RobotScript.awaitMoreLines;
import static org.kheperasim.link.robot.RobotScript.awaitReceived;
import static org.kheperasim.link.robot.RobotScript.count;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Tag;
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
import org.kheperasim.link.testcontrollers.Overriding;
import org.kheperasim.link.testcontrollers.Returner;
import org.kheperasim.link.testcontrollers.Thrower;
import org.kheperasim.link.timing.LinkTiming;

/**
 * A controller runs on the fake robot over a socat pty pair (robot-link's side through jSerialComm).
 * Every test ends by checking that the last line the robot received is {@code D,0,0}.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy, and each step waits for what the robot receives, not for a fixed time.
 */
@Tag("timing")
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotRunPtyTest {
    @TempDir
    Path dir;

    private final List<String> console = Collections.synchronizedList(new ArrayList<>());
    private final Consumer<String> out = line -> console.add(line);

    private RobotRun.Result run(FakeRobotOnPty fake, Class<?> controller, RobotSettings settings, long millis,
            RobotScript script) throws Exception {
        SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
        try (Session s = new Session(link, LinkTiming.atBaud(38400), new Session.Options(150, 3, 100, 2000))) {
            s.open();
            RobotRun run = new RobotRun(new RobotBackend(s, settings, out), controller, out);
            return RobotScript.play(script, fake.robot(), run, millis);
        }
    }

    private static void assertStoppedLast(FakeKhepera robot) {
        assertEquals("D,0,0", robot.lastReceived(), "the last line the robot received; all: " + tail(robot.received()));
    }

    private static List<String> tail(List<String> l) {
        return RobotScript.tail(l);
    }

    @Test
    void wallFollowerRunsUnchangedAndItsMotorCommandsArrive() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            Class<?> wf = new ControllerLoader(List.of()).load("WallFollower");
            assertEquals("org.kheperasim.controllers.WallFollower", wf.getName());
            RobotRun.Result r = run(fake, wf, RobotSettings.defaults(), 30_000, (rb, run) -> {
                awaitReceived(rb, "D,3,3", 0);          // findwall(): driving ahead at (3, 3)
                rb.setProximity(0, 0, 700, 0, 0, 0, 0, 0);
                awaitReceived(rb, "D,2,-2", 0);         // wall ahead: turn on the spot (2, -2)
                rb.setProximity(700, 0, 0, 0, 0, 0, 0, 0);
                awaitReceived(rb, "D,3,-1", 0);         // wall on the left only: follow it (3, -1)
                run.requestStop("the moves were seen");
            });
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
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
            RobotRun.Result r = run(fake, step, RobotSettings.defaults(), 30_000, (rb, run) -> {
                awaitReceived(rb, "D,6,6", 0);          // nothing in sight: cruising at (6, 6)
                rb.setProximity(0, 0, 700, 0, 0, 0, 0, 0);
                awaitReceived(rb, "D,4,-4", 0);         // something ahead on the left: a later step spins right (4, -4)
                run.requestStop("the steps were seen");
            });
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
            List<String> d = robot.received().stream().filter(l -> l.startsWith("D")).toList();
            int cruise = d.indexOf("D,6,6");
            int spin = d.indexOf("D,4,-4");
            assertTrue(cruise >= 0 && cruise < spin, "the steps' speeds reached the robot, in order: " + d);
            assertTrue(r.pollRateHz() > 5, "the sensors were polled for the steps: " + r.pollRateHz());
            assertStoppedLast(robot);
        }
    }

    @Test
    void aControllerWhoseKillControlAndInterruptBlockIsLeftBehindWithTheRobotStopped() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            long start = System.nanoTime();
            RobotRun.Result r = run(fake, Overriding.class, RobotSettings.defaults(), 30_000, (rb, run) -> {
                awaitReceived(rb, "D,5,5", 0);          // started, through its own start()
                run.requestStop("the run was seen");
            });
            // Its killControl() and interrupt() block 30 s each: robot-link waits the 2 s grace for them, not longer.
            assertTrue(System.nanoTime() - start < 25_000_000_000L, "the run ended after the grace: " + console);
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
            assertTrue(console.stream().anyMatch(l -> l.contains("did not stop within 2 s of being asked")), console.toString());
            assertStoppedLast(robot);
        }
    }

    @Test
    void garbageDroppedLateAndBannerFaultsAreSurvived() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 30_000, (rb, run) -> {
                awaitReceived(rb, "D,5,5", 0);          // the run is going
                // Each fault waits for the command it spoils (and its retry) before the next is set.
                rb.noiseBeforeNextReply("\u0000\u00ffgarbage\r\n");
                awaitMoreLines(rb, 3);
                rb.dropReplies(1);
                awaitMoreLines(rb, 3);
                rb.lateReply(500);
                Thread.sleep(600);                      // the late reply comes while the run goes on
                awaitMoreLines(rb, 3);
                long before = count(rb, "D,5,5");
                rb.resetAtNextCommand();
                awaitReceived(rb, "D,5,5", before);     // the reset robot got its speeds again
                awaitMoreLines(rb, 3);
                run.requestStop("the faults were met");
            });
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
            // The dropped reply and the reset cost a retry each; the late one does when the session's 150 ms
            // wait ends before the reply comes 500 ms late, which a saturated machine may not let happen.
            assertTrue(r.stats().retries() >= 2, "the faults cost retries: " + r.stats());
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
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 30_000, (rb, run) -> {
                awaitReceived(rb, "D,5,5", 0);
                long before = count(rb, "D,5,5");
                rb.resetAtNextCommand();
                awaitReceived(rb, "D,5,5", before);     // sent again after the reset (which stopped the wheels)
                awaitMoreLines(rb, 1);
                int[] s = rb.speeds();
                seen[0] = s[0];
                seen[1] = s[1];
                run.requestStop("the speeds were seen");
            });
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail());
            assertEquals(5, seen[0], "after a reset (which stops the wheels) the controller's speeds are sent again");
            assertStoppedLast(robot);
        }
    }

    @Test
    void aRobotThatFallsSilentIsReportedAndToldToStop() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            FakeKhepera robot = fake.robot();
            long start = System.nanoTime();
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 20_000, (rb, run) -> {
                awaitReceived(rb, "D,5,5", 0);          // the run is going, then the robot says nothing more
                rb.setSilent(true);
            });
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
            RobotRun.Result r = run(fake, Forward.class, RobotSettings.defaults(), 20_000, (rb, run) -> {
                awaitReceived(rb, "D,5,5", 0);          // the run is going, then the cable is pulled
                fake.pty().kill();
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
            RobotRun.Result r = run(fake, Thrower.class, RobotSettings.defaults(), 10_000, RobotScript.NOTHING);
            assertEquals(RobotRun.End.FAILED, r.end());
            assertTrue(r.detail().contains("student bug"), r.detail());
            assertTrue(fake.robot().received().contains("D,6,6"));
            assertStoppedLast(fake.robot());
        }
    }

    @Test
    void aControllerThatReturnsWithWheelsTurningStopsTheRobot() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, Returner.class, RobotSettings.defaults(), 10_000, RobotScript.NOTHING);
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
            RobotRun.Result r = run(fake, Fast.class, settings, 800, RobotScript.NOTHING);
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
