package org.kheperasim.link.robot;

import java.util.Locale;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;
import org.kheperasim.link.timing.LinkTiming;

/** Measures the poll rate a link reaches: the poll loop alone, no controller, for a while. */
public final class PollBench {
    /**
     * @param baud the line speed
     * @param rateHz poll cycles per second reached
     * @param modelHz what the link timing model predicts at that speed for the values the robot last reported
     * @param cycles cycles run
     * @param stats the session's counts and round-trip times
     */
    public record Result(int baud, double rateHz, double modelHz, long cycles, Session.Stats stats) {
        /** @return one line for people */
        public String describe() {
            return String.format(Locale.ROOT, "%6d baud: %6.1f poll cycles/s (N, O, H), %5.2f ms per cycle;"
                    + " the timing model predicts %6.1f/s; mean round trip %.2f ms, %d retries",
                    baud, rateHz, 1000.0 / Math.max(rateHz, 1e-9), modelHz, stats.meanRoundTripNanos() / 1e6,
                    stats.retries());
        }
    }

    private PollBench() {
    }

    /**
     * @param session an open session
     * @param baud its line speed, for the model's prediction
     * @param millis how long to poll, ms
     * @return what was reached; the robot has been sent {@code D,0,0}
     * @throws SessionException when the robot stops answering
     */
    public static Result measure(Session session, int baud, long millis) throws SessionException, InterruptedException {
        RobotBackend backend = new RobotBackend(session, RobotSettings.defaults(), line -> { });
        try {
            backend.start(10_000);
            long end = System.nanoTime() + millis * 1_000_000L;
            while (System.nanoTime() < end && backend.failure() == null) {
                Thread.sleep(20);
            }
            if (backend.failure() != null) {
                throw backend.failure();
            }
            double rate = backend.pollRateHz();
            // The model's rate for the values the robot last reported: its replies are as long as they are.
            int[] proximity = new int[8];
            int[] light = new int[8];
            for (int i = 0; i < 8; i++) {
                proximity[i] = backend.proximity(i);
                light[i] = backend.ambientLight(i);
            }
            int[] counters = {backend.leftPosition(), backend.rightPosition()};
            return new Result(baud, rate, 1e9 / LinkTiming.atBaud(baud).pollCycleNanos(proximity, light, counters),
                    backend.cycles(), session.stats());
        } finally {
            backend.stop();
        }
    }
}
