package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * A robot that reboots mid-session (its boot banner arrives; it has stopped its wheels and its
 * counters start again at 0) is reported, gets its speeds again, and the positions the controller
 * reads carry on from where they were instead of jumping back to 0.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy, and each step waits for what the robot receives, not for a fixed time.
 */
@Tag("timing")
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RebootTest {
    @TempDir
    Path dir;

    @Test
    void aRebootIsReportedAndTheCountersCarryOn() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null);
                Session session = new Session(SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400)),
                        LinkTiming.defaults(), Session.Options.defaults())) {
            session.open();
            List<String> console = new CopyOnWriteArrayList<>();
            RobotBackend backend = new RobotBackend(session, RobotSettings.defaults(), console::add);
            backend.start(10_000);
            try {
                backend.setSpeeds(10, 10);
                // The wheels turn (as long as a busy machine needs for the polls to tell).
                long turning = System.nanoTime() + 20_000_000_000L;
                while (backend.leftPosition() <= 100 && System.nanoTime() < turning) {
                    Thread.sleep(10);
                }
                int before = backend.leftPosition();
                assertTrue(before > 100, "the wheels turned: " + before);
                fake.robot().resetAtNextCommand();
                long deadline = System.nanoTime() + 20_000_000_000L;
                while (console.stream().noneMatch(l -> l.contains("rebooted")) && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                }
                assertTrue(console.stream().anyMatch(l -> l.contains("rebooted")), "the reboot is reported: " + console);
                // The positions read after the reboot (the next position poll, H): carried on, not back near 0.
                long polls = fake.robot().received().stream().filter("H"::equals).count();
                long read = System.nanoTime() + 20_000_000_000L;
                while (fake.robot().received().stream().filter("H"::equals).count() < polls + 2 && System.nanoTime() < read) {
                    Thread.sleep(10);
                }
                int after = backend.leftPosition();
                assertTrue(after >= before, "the position carries on over the reboot: " + before + " then " + after);
                assertTrue(fake.robot().speeds()[0] == 10, "the speeds were sent again after the reboot");
            } finally {
                backend.stop();
            }
        }
    }
}
