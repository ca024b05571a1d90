package org.kheperasim.link.session;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.Reply;
import org.kheperasim.link.timing.LinkTiming;

/**
 * The session over a real pty pair, opened through jSerialComm, against the fake robot.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy. What it checks is the protocol's logic (noise skipped, a dropped reply
 * resent, a stale reply thrown away), so each test holds however late the machine lets a reply come:
 * a reply the test expects in time has {@link #REPLY_MILLIS} (a starved fake robot and socat at load
 * 30 on 2 cores answer within it), a reply meant to miss its time misses it by construction (dropped,
 * or sent later than the wait by the fake's own clock), and a late reply is waited for, not slept for.
 *
 * <p>The methods run at once (each its own socat pair, fake robot and session in its own folder): most of each is a
 * reply's time limit running out.
 */
@Tag("timing")
@Execution(ExecutionMode.CONCURRENT)
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SessionPtyTest {
    @TempDir
    Path dir;

    private static Session session(FakeRobotOnPty fake, Session.Options options) throws Exception {
        SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
        return new Session(link, LinkTiming.atBaud(38400), options);
    }

    /**
     * How long a reply may take beyond its wire time. 150 ms (a real client's figure) was too short under
     * load: a loaded build once timed out an answered command, counting a retry the test forbids.
     */
    static final long REPLY_MILLIS = 1500;

    private static Session.Options fast() {
        return new Session.Options(REPLY_MILLIS, 3, 100, 2000);
    }

    @Test
    void throwsAwayTheBootBannerAndReportsTheVersions() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            fake.robot().sendBanner();
            Session.Versions v = s.open();
            assertEquals(new Session.Versions("5.02", "5.01"), v);
            // Thrown away while waiting for quiet (as lines) or, when a loaded machine relays it later, before the
            // B command (as characters).
            assertTrue(s.stats().skippedLines() >= 2 || s.stats().discardedChars() >= FakeKhepera.BANNER.length() - 2,
                    "the banner was thrown away: " + s.stats());
        }
    }

    @Test
    void survivesNoiseBeforeAReply() throws Exception {
        noiseIsSurvived(0);
    }

    /**
     * The same on a machine so loaded that every reply comes 400 ms late (at load 30 on 2 cores the fake robot's
     * thread and socat wait their turn): nothing the test counts changes.
     */
    @Test
    void survivesNoiseBeforeAReplyFromAStarvedRobot() throws Exception {
        noiseIsSurvived(400);
    }

    private void noiseIsSurvived(long starvedMillis) throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.robot().setReplyDelay(starvedMillis);
            fake.robot().setProximity(1, 2, 3, 4, 5, 6, 7, 8);
            fake.robot().noiseBeforeNextReply("\u0000\u00ff#%garbage\r\nn,1,2\r\nxx\n");
            Reply r = s.exchange(new Command.ReadProximity());
            assertEquals("n,1,2,3,4,5,6,7,8", r.encode());
            assertEquals(0, s.stats().retries(), "whole noise lines are skipped while waiting");
            assertTrue(s.stats().skippedLines() >= 3, s.stats().toString());
            // Noise glued to the front of the reply spoils it: the command is sent again.
            fake.robot().noiseBeforeNextReply("\u0007zz");
            assertEquals("n,1,2,3,4,5,6,7,8", s.exchange(new Command.ReadProximity()).encode());
            assertEquals(1, s.stats().retries());
        }
    }

    @Test
    void resendsACommandWhoseReplyWasDropped() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.robot().dropReplies(2);
            s.exchange(new Command.SetSpeed(5, 5));
            assertEquals(2, s.stats().retries());
            assertEquals(3, fake.robot().received().stream().filter("D,5,5"::equals).count());
        }
    }

    @Test
    void aLateReplyDoesNotAnswerTheNextCommand() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.robot().setProximity(9, 9, 9, 9, 9, 9, 9, 9);
            // Later than the session waits, by the fake's clock, which starts after the session's.
            fake.robot().lateReply(REPLY_MILLIS + 300);
            assertEquals("n,9,9,9,9,9,9,9,9", s.exchange(new Command.ReadProximity()).encode());
            fake.robot().awaitLateReplies(1, 30_000); // the late reply to the first N has been sent
            Thread.sleep(500);                         // and crossed the pty
            fake.robot().setProximity(1, 1, 1, 1, 1, 1, 1, 1);
            assertEquals("n,1,1,1,1,1,1,1,1", s.exchange(new Command.ReadProximity()).encode(),
                    "the stale reply was thrown away, not taken for the new one");
        }
    }

    @Test
    void aResetMidSessionIsSurvived() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.robot().resetAtNextCommand();
            s.exchange(new Command.SetSpeed(4, 4));
            assertEquals(1, s.stats().retries(), "the banner did not answer D; D was sent again");
            assertEquals(4, fake.robot().speeds()[0], "and obeyed after the reset");
        }
    }

    @Test
    void aSilentRobotIsReportedNamingTheCommand() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast().withRetries(1))) {
            s.open();
            fake.robot().setSilent(true);
            SessionException e = assertThrows(SessionException.class, () -> s.exchange(new Command.ReadLight()));
            assertEquals(SessionException.Kind.NO_REPLY, e.kind());
            assertTrue(e.getMessage().contains("'O'") && e.getMessage().contains(fake.hostPath()), e.getMessage());
        }
    }

    @Test
    void anUnknownCommandIsReportedNamingIt() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.robot().setGripperFitted(false);
            Command g = Command.Turret.gripper(new org.kheperasim.link.protocol.TurretCommand.Barrier());
            SessionException e = assertThrows(SessionException.class, () -> s.exchange(g));
            assertEquals(SessionException.Kind.REFUSED, e.kind());
            assertTrue(e.getMessage().contains("'T,1,G'"), e.getMessage());
            assertEquals(1, fake.robot().received().stream().filter("T,1,G"::equals).count(), "not retried");
        }
    }

    @Test
    void theFarEndVanishingIsReportedAsALostLink() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null); Session s = session(fake, fast())) {
            s.open();
            fake.pty().kill();
            long start = System.nanoTime();
            SessionException e = assertThrows(SessionException.class, () -> {
                for (int i = 0; i < 100; i++) {
                    s.exchange(new Command.ReadProximity());
                }
            });
            assertEquals(SessionException.Kind.LINK_LOST, e.kind(), e.getMessage());
            assertTrue(e.getMessage().contains("'N'") && e.getMessage().contains("has gone"), e.getMessage());
            assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5), "reported promptly");
        }
    }
}
