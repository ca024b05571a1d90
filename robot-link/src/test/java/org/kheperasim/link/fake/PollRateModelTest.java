package org.kheperasim.link.fake;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.robot.PollBench;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * The link timing model predicts the poll rate robot-link reaches over a real serial line (a socat
 * pty pair) against the fake robot, which paces each reply by its real length: within 10 % at
 * 9600, 38400 and 115200 baud, for the values a robot in an open arena sends (two-digit proximity,
 * three-digit light). The fake once measured 28.5 cycles/s at 38400 baud because its bench set
 * every proximity value to 1000: four-digit numbers make the longest replies.
 *
 * <p>A wall-clock measurement: a loaded machine can only lower it, so the best of up to 25 short
 * windows (about a second each at 38400 baud) counts; on a quiet machine the first agrees.
 * Tagged {@code rate}, not {@code timing}: with every core saturated a rate is whatever the load
 * leaves, so CI's busy-machine step does not run it (the plain build does).
 */
@Tag("rate")
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PollRateModelTest {
    private static final int[] PROXIMITY = {15, 22, 18, 9, 25, 14, 19, 21};
    private static final int[] LIGHT = {480, 475, 482, 490, 478, 481, 479, 485};

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0} baud")
    @ValueSource(ints = {9600, 38400, 115200})
    void theModelPredictsThePollRateOnTheWire(int baud) throws Exception {
        PtyPair.assumeSocat();
        LinkTiming timing = LinkTiming.atBaud(baud);
        double model = 1e9 / timing.pollCycleNanos(PROXIMITY, LIGHT, new int[] {0, 0});
        // Load can only slow the loop down: the best of up to 25 windows of about 40 cycles is
        // the rate the wire allows; stop as soon as one agrees.
        double best = 0;
        Path folder = java.nio.file.Files.createDirectories(dir.resolve("pty"));
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(folder, timing);
                Session s = new Session(SerialLink.open(SerialSettings.khepera(fake.hostPath(), baud)), timing,
                        Session.Options.defaults())) {
            fake.robot().setProximity(PROXIMITY);
            fake.robot().setLight(LIGHT);
            s.open();
            long window = StrictMath.max(400, (long) (40_000 / model));
            for (int attempt = 0; attempt < 25 && StrictMath.abs(best / model - 1) > 0.05; attempt++) {
                best = StrictMath.max(best, PollBench.measure(s, baud, window).rateHz());
            }
        }
        System.out.printf(Locale.ROOT, "%6d baud: fake robot over a pty %.1f cycles/s, model %.1f/s%n", baud, best, model);
        assertEquals(1, best / model, 0.10, "measured " + best + "/s vs model " + model + "/s");
    }
}
