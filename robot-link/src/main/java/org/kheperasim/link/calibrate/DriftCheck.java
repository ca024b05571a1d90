package org.kheperasim.link.calibrate;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;

/**
 * {@code calibrate --check}: with the robot facing the wall at the calibration's first gap, it
 * backs away through a few of the calibration's blocks, reads the sensors there and compares them
 * with the calibration's means; the robot has drifted when the median relative change of the lit
 * readings (20..1000 counts then) passes the threshold.
 */
public final class DriftCheck {
    private DriftCheck() {
    }

    /**
     * @param session an open session
     * @param answers the person
     * @param out the console
     * @param calibration the calibration file
     * @param readings readings per point
     * @param scanMillis time between readings
     * @param threshold the relative change that counts as drift (0.1: 10 %)
     * @return whether the robot has drifted past the threshold
     */
    public static boolean drifted(Session session, Answers answers, PrintWriter out, Path calibration, int readings,
            long scanMillis, double threshold) throws IOException, SessionException {
        Calibration.Ahead ahead = Calibration.ahead(calibration);
        double[] gaps = ahead.gapsMm();
        double step = gaps.length > 1 ? gaps[1] - gaps[0] : 0;
        answers.pause("check.placed",
                String.format(Locale.ROOT, "Put the robot facing the white wall straight on, its front"
                + " %.1f mm from it (by ruler), as in the calibration;", gaps[0]));
        RobotMoves moves = new RobotMoves(session, scanMillis);
        int stepPulses = (int) StrictMath.rint(step / ahead.mmPerPulse());
        List<Double> changes = new ArrayList<>();
        int last = StrictMath.min(gaps.length - 1, 6);
        for (int t = 0; t <= last; t++) {
            if (t > 0) {
                moves.moveBy(-stepPulses, -stepPulses);
            }
            if (t % 2 == 1 || t == last) {
                double[] now = RobotMoves.mean(moves.readings(false, readings));
                for (int s = 0; s < now.length; s++) {
                    double then = ahead.means()[t][s];
                    if (then >= 20 && then <= 1000) {
                        changes.add(now[s] / then - 1);
                    }
                }
                out.println(String.format(Locale.ROOT, "at %.1f mm: now %s, calibrated %s", gaps[t], round(now),
                        round(ahead.means()[t])));
            }
        }
        if (changes.isEmpty()) {
            throw new IllegalArgumentException("calibration " + calibration + " has no lit reading (20..1000) at the"
                    + " checked gaps: check that its wall series faced the wall");
        }
        double[] c = changes.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        double median = c.length % 2 == 1 ? c[c.length / 2] : (c[c.length / 2 - 1] + c[c.length / 2]) / 2;
        boolean drifted = StrictMath.abs(median) > threshold;
        out.println(String.format(Locale.ROOT,
                "median change of %d lit readings: %+.1f %% (threshold %.1f %%): %s", c.length,
                100 * median, 100 * threshold,
                drifted ? "DRIFTED, calibrate the robot again" : "within the calibration"));
        out.flush();
        session.exchange(session.dialect().setSpeeds(0, 0));
        return drifted;
    }

    private static String round(double[] v) {
        return Arrays.toString(Arrays.stream(v).map(StrictMath::rint).mapToInt(x -> (int) x).toArray());
    }
}
