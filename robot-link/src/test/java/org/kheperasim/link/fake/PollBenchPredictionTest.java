package org.kheperasim.link.fake;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.robot.PollBench;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;

/**
 * {@code khepera-link bench} predicts the poll rate from the replies the robot actually sent: a
 * robot with one-digit proximity values (short {@code n} replies) is predicted faster than one with
 * four-digit values, each exactly as the timing model gives for its replies. Checks the prediction
 * and the characters counted, never the wall-clock rate.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PollBenchPredictionTest {
    private static final int[] LIGHT = {480, 475, 482, 490, 478, 481, 479, 485};

    @TempDir
    Path dir;

    @ParameterizedTest(name = "proximity {0}")
    @ValueSource(ints = {7, 1000})
    void thePredictionFollowsTheRepliesReceived(int proximity) throws Exception {
        PtyPair.assumeSocat();
        int[] prox = new int[8];
        java.util.Arrays.fill(prox, proximity);
        LinkTiming timing = LinkTiming.atBaud(38400);
        int chars = LinkTiming.replyChars(PollStep.PROXIMITY, prox) + LinkTiming.replyChars(PollStep.LIGHT, LIGHT)
                + LinkTiming.replyChars(PollStep.ENCODERS, new int[] {0, 0});
        double expected = 1e9 / timing.pollCycleNanos(prox, LIGHT, new int[] {0, 0});
        Path folder = Files.createDirectories(dir.resolve("pty"));
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(folder, timing);
                Session s = new Session(SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400)), timing,
                        Session.Options.defaults())) {
            fake.robot().setProximity(prox);
            fake.robot().setLight(LIGHT);
            s.open();
            PollBench.Result r = PollBench.measure(s, 38400, 400);
            System.out.println(r.describe());
            assertEquals(chars, r.replyCharsPerCycle(), 0.5, "characters of a cycle's replies: " + r.describe());
            assertEquals(expected, r.modelHz(), expected * 0.01, r.describe());
        }
    }
}
