package org.kheperasim.link.robot;

import java.util.Locale;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;

/** Measures the poll rate a link reaches: the poll loop alone, no controller, for a while. */
public final class PollBench {
    /**
     * @param baud the line speed
     * @param rateHz poll cycles per second reached
     * @param modelHz what the link timing model predicts at that speed for the replies the robot
     *     actually sent during the bench (their mean length)
     * @param replyCharsPerCycle the mean characters of a cycle's three replies, CR LF included
     * @param cycles cycles run
     * @param stats the session's counts and round-trip times
     */
    public record Result(int baud, double rateHz, double modelHz, double replyCharsPerCycle, long cycles,
            Session.Stats stats) {
        /** @return one line for people */
        public String describe() {
            return String.format(Locale.ROOT, "%6d baud: %6.1f poll cycles/s (N, O, H), %5.2f ms per cycle;"
                    + " the timing model predicts %6.1f/s for the replies received (%.1f characters a cycle);"
                    + " mean round trip %.2f ms, %d retries",
                    baud, rateHz, 1000.0 / Math.max(rateHz, 1e-9), modelHz, replyCharsPerCycle,
                    stats.meanRoundTripNanos() / 1e6, stats.retries());
        }
    }

    private static final PollStep[] STEPS = {PollStep.PROXIMITY, PollStep.LIGHT, PollStep.ENCODERS};

    private PollBench() {
    }

    private static long[][] replies(Session session) {
        long[][] r = new long[STEPS.length][];
        for (int k = 0; k < STEPS.length; k++) {
            // The encoders' letter is the dialect's (H on a Khepera, Q on an e-puck).
            char letter = STEPS[k] == PollStep.ENCODERS
                    ? session.dialect().readCounters().letter() : STEPS[k].command();
            r[k] = session.replies(letter);
        }
        return r;
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
            // Count from here: the start's priming exchanges are not the bench's.
            long[][] before = replies(session);
            long end = System.nanoTime() + millis * 1_000_000L;
            while (System.nanoTime() < end && backend.failure() == null) {
                Thread.sleep(20);
            }
            if (backend.failure() != null) {
                throw backend.failure();
            }
            double rate = backend.pollRateHz();
            // The model's cycle for the replies the robot really sent: each step's command, gap and
            // turnaround, and its replies' mean length over the bench.
            long[][] after = replies(session);
            LinkTiming timing = LinkTiming.atBaud(baud);
            double perCycle = 0;
            double cycleNanos = 0;
            for (int k = 0; k < STEPS.length; k++) {
                long n = after[k][0] - before[k][0];
                double chars = n == 0 ? STEPS[k].replyChars() : (double) (after[k][1] - before[k][1]) / n;
                perCycle += chars;
                cycleNanos += timing.commandNanos(STEPS[k]) + chars * timing.wireNanos(1000) / 1000.0;
            }
            return new Result(baud, rate, 1e9 / cycleNanos, perCycle, backend.cycles(), session.stats());
        } finally {
            backend.stop();
        }
    }
}
