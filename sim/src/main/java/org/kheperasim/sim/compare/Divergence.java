package org.kheperasim.sim.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Where a real run and its simulation diverge: per sensor the RMS difference over time, both
 * odometry paths (dead reckoning from each run's wheel counters with the same wheel numbers), and
 * the first moment the paths are farther apart than a threshold.
 *
 * @param sensorRms per sensor, RMS of real minus simulated reading over the real run's samples, counts
 * @param times the real run's sample times, s
 * @param realPath odometry of the real run, {@code [i] = {x, y}} mm, from its start
 * @param simPath odometry of the simulation at the same times
 * @param thresholdMm the parting threshold, mm
 * @param partedAt the first time the paths are more than the threshold apart, s; NaN: never
 * @param maxApartMm the largest distance between them, mm
 */
public record Divergence(double[] sensorRms, double[] times, double[][] realPath, double[][] simPath,
        double thresholdMm,
        double partedAt, double maxApartMm) {

    /**
     * @param real the real run
     * @param sim its simulation
     * @param mmPerPulse the wheels' travel per pulse, mm
     * @param wheelBaseMm the wheel base, mm
     * @param thresholdMm how far apart the paths part
     * @return the divergence
     */
    public static Divergence of(Track real, Track sim, double mmPerPulse, double wheelBaseMm, double thresholdMm) {
        int n = real.samples().size();
        int sensors = real.samples().get(0).proximity().length;
        double[] sum = new double[sensors];
        double[] times = new double[n];
        double[][] rp = new double[n][];
        double[][] sp = new double[n][];
        Odometry ro = new Odometry(real.samples().get(0), mmPerPulse, wheelBaseMm);
        Track.Point s0 = sim.at(real.samples().get(0).seconds());
        Odometry so = new Odometry(s0, mmPerPulse, wheelBaseMm);
        double parted = Double.NaN;
        double max = 0;
        for (int k = 0; k < n; k++) {
            Track.Point r = real.samples().get(k);
            Track.Point s = sim.at(r.seconds());
            for (int i = 0; i < sensors; i++) {
                double d = r.proximity()[i] - s.proximity()[i];
                sum[i] += d * d;
            }
            times[k] = r.seconds();
            rp[k] = ro.to(r);
            sp[k] = so.to(s);
            double apart = StrictMath.hypot(rp[k][0] - sp[k][0], rp[k][1] - sp[k][1]);
            max = StrictMath.max(max, apart);
            if (apart > thresholdMm && Double.isNaN(parted)) {
                parted = r.seconds();
            }
        }
        double[] rms = new double[sensors];
        for (int i = 0; i < sensors; i++) {
            rms[i] = StrictMath.sqrt(sum[i] / n);
        }
        return new Divergence(rms, times, rp, sp, thresholdMm, parted, max);
    }

    /** Dead reckoning from wheel counters: x ahead at the start, y to the left, mm. */
    private static final class Odometry {
        private final double mmPerPulse;
        private final double base;
        private int left;
        private int right;
        private double x;
        private double y;
        private double heading;

        Odometry(Track.Point start, double mmPerPulse, double base) {
            this.mmPerPulse = mmPerPulse;
            this.base = base;
            this.left = start.left();
            this.right = start.right();
        }

        double[] to(Track.Point p) {
            double l = (p.left() - left) * mmPerPulse;
            double r = (p.right() - right) * mmPerPulse;
            left = p.left();
            right = p.right();
            double turn = (r - l) / base;
            double mid = heading + turn / 2;
            x += (l + r) / 2 * StrictMath.cos(mid);
            y += (l + r) / 2 * StrictMath.sin(mid);
            heading += turn;
            return new double[] {x, y};
        }
    }

    /** @return the divergence as text */
    public String text() {
        StringBuilder sb = new StringBuilder("per sensor RMS, real minus simulated, counts:");
        for (double v : sensorRms) {
            sb.append(String.format(Locale.ROOT, " %.1f", v));
        }
        sb.append(String.format(Locale.ROOT, "%nodometry: the paths are at most %.1f mm apart; ", maxApartMm));
        sb.append(Double.isNaN(partedAt) ? String.format(Locale.ROOT, "never more than %.1f mm%n", thresholdMm)
                : String.format(Locale.ROOT, "first more than %.1f mm apart at %.3f s%n", thresholdMm, partedAt));
        return sb.toString();
    }

    /** @return the divergence as JSON: sensorRms, thresholdMm, partedAt (null: never), maxApartMm, and both paths */
    public String json() {
        StringBuilder sb = new StringBuilder("{\"sensorRms\":[");
        for (int i = 0; i < sensorRms.length; i++) {
            sb.append(i == 0 ? "" : ",").append(String.format(Locale.ROOT, "%.3f", sensorRms[i]));
        }
        sb.append(String.format(Locale.ROOT,
                "],\"thresholdMm\":%.3f,\"partedAt\":%s,\"maxApartMm\":%.3f,\"samples\":[", thresholdMm,
                Double.isNaN(partedAt) ? "null" : String.format(Locale.ROOT, "%.4f", partedAt), maxApartMm));
        List<String> rows = new ArrayList<>();
        for (int k = 0; k < times.length; k++) {
            rows.add(String.format(Locale.ROOT, "{\"t\":%.4f,\"real\":[%.2f,%.2f],\"sim\":[%.2f,%.2f]}",
                    times[k], realPath[k][0],
                    realPath[k][1], simPath[k][0], simPath[k][1]));
        }
        return sb.append(String.join(",", rows)).append("]}").toString();
    }
}
