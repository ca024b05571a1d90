package org.kheperasim.sim.engine.robot;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Fits a {@link Response.Table} to measured wall readings (a {@link SampleTable}'s, or a
 * calibration's), so that the engine's beam rule ({@link WallReading}) reproduces them: one table
 * for the robot's sensors, a gain per sensor, the offset and the noise.
 *
 * <p>The table is first filled from the readings binned by the sensor-to-wall distance and the
 * wall's angle off the sensor's axis, then refined: each reading's strongest beam is pulled towards
 * it (a least-squares step per table cell, the gains refitted after each pass), every row kept
 * falling with distance.
 */
public final class SampleFit {
    /** The table's beam angles, degrees off the sensor's axis. */
    static final double[] ANGLES_DEG = {0, 10, 20, 30, 40, 50, 60, 70, 80};
    /** The table's distances, mm along a beam: 0..48 in 2 mm, then nothing at 60. */
    static final double[] DISTANCES_MM = distances();
    private static final int PASSES = 60;

    /** One measured reading of a sensor with a straight white wall in front of the robot. */
    public record Sample(int sensor, double gapMm, double objectRightDeg, double counts) {
    }

    /** Where a sampled object lies along a sensor's beam: a straight wall, or a disc (a cap, a robot). */
    @FunctionalInterface
    public interface Geometry {
        /** A straight wall ({@link WallReading#beamDistanceMm}). */
        Geometry WALL = WallReading::beamDistanceMm;

        /**
         * @param type the robot
         * @param sensor a sensor
         * @param gapMm the object's gap from the body's surface, mm
         * @param objectRightDeg where its nearest point lies, degrees to the right of ahead
         * @param beamDeg a beam's angle off the sensor's axis, degrees counter-clockwise
         * @return the distance along the beam to the object, mm; infinity if the beam misses it
         */
        double beamDistanceMm(RobotType type, int sensor, double gapMm, double objectRightDeg, double beamDeg);

        /** @param radiusMm the disc's radius, mm @return an upright cylinder of that radius (a cap, a robot's body) */
        static Geometry disc(double radiusMm) {
            return (type, sensor, gapMm, objectRightDeg, beamDeg) -> {
                RobotType.Sensor s = type.sensor(sensor);
                double th = StrictMath.toRadians(objectRightDeg);
                double c = type.body().radiusMm() + gapMm + radiusMm;
                double wx = s.xMm() - c * StrictMath.cos(th);
                double wy = s.yMm() + c * StrictMath.sin(th);
                double b = StrictMath.toRadians(s.headingDeg() + beamDeg);
                double wb = wx * StrictMath.cos(b) + wy * StrictMath.sin(b);
                double ww = wx * wx + wy * wy - radiusMm * radiusMm;
                if (ww <= 0) {
                    return 0;
                }
                double disc = wb * wb - ww;
                if (disc < 0 || wb > 0) {
                    return Double.POSITIVE_INFINITY;
                }
                return -wb - StrictMath.sqrt(disc);
            };
        }
    }

    /**
     * The fit.
     *
     * @param table the response, for every sensor
     * @param gains each sensor's gain on it
     * @param offset the reading with nothing in range, counts
     * @param noiseAbs the readings' spread with nothing in range, standard deviation, counts
     * @param noiseRel the remaining spread relative to the signal (fit error included)
     */
    public record Result(Response.Table table, double[] gains, double offset, double noiseAbs, double noiseRel) {
        /**
         * @param i a sensor @param gapMm wall gap, mm @param objectRightDeg wall direction @return the fit's reading
         */
        public double predict(RobotType type, int i, double gapMm, double objectRightDeg) {
            return WallReading.reading(type, table, i, gains[i], offset, gapMm, objectRightDeg);
        }
    }

    private SampleFit() {
    }

    private static double[] distances() {
        double[] d = new double[26];
        for (int i = 0; i < 25; i++) {
            d[i] = 2 * i;
        }
        d[25] = 60;
        return d;
    }

    /**
     * @param table sampled readings
     * @param keep which distance blocks to take
     * @return every reading of those blocks as a sample (sensor, gap, angle, counts)
     */
    public static List<Sample> samples(SampleTable table, java.util.function.IntPredicate keep) {
        List<Sample> out = new java.util.ArrayList<>();
        for (int t = 0; t < table.blocks(); t++) {
            if (!keep.test(t)) {
                continue;
            }
            for (int k = 0; k < table.angles(); k++) {
                for (int i = 0; i < table.sensors(); i++) {
                    out.add(new Sample(i, table.gapMm(t), table.objectRightDeg(k), table.counts(t, k, i)));
                }
            }
        }
        return out;
    }

    /**
     * @param type the robot the readings come from (body radius, sensor poses)
     * @param samples its readings
     * @return the fitted response
     */
    public static Result fit(RobotType type, List<Sample> samples) {
        return fit(type, samples, true);
    }

    /** As {@link #fit(RobotType, List)}; without {@code perSensorGains} every gain stays 1. */
    static Result fit(RobotType type, List<Sample> samples, boolean perSensorGains) {
        return fit(type, samples, Geometry.WALL, perSensorGains, Double.NaN);
    }

    /**
     * @param type the robot the readings come from
     * @param samples its readings of one kind of object
     * @param geometry where that object lies along the beams
     * @param perSensorGains fit a gain per sensor (else every gain stays 1)
     * @param fixedOffset the reading with nothing in range, counts, or NaN: the median of the far readings
     * @return the fitted response
     */
    public static Result fit(RobotType type, List<Sample> samples, Geometry geometry, boolean perSensorGains,
            double fixedOffset) {
        return fit(type, samples, geometry, perSensorGains, fixedOffset, null);
    }

    /**
     * As {@link #fit(RobotType, List, Geometry, boolean, double)}, refining a given table (on this fit's grid)
     * instead of one binned from the readings: cells the readings never reach keep the start's values, so a
     * sensor fitted on its own readings keeps the shared table where it saw nothing.
     *
     * @param start the table to start from, {@code [angle][distance]} on {@link #ANGLES_DEG} and
     *     {@link #DISTANCES_MM}, or null: binned from the readings
     */
    public static Result fit(RobotType type, List<Sample> samples, Geometry geometry, boolean perSensorGains,
            double fixedOffset, double[][] start) {
        int nd = DISTANCES_MM.length;
        int na = ANGLES_DEG.length;
        int rays = 2 * na - 1;
        int n = samples.size();
        int sensors = type.sensorCount();
        double[][] dist = new double[n][rays];
        double[] axisDeg = new double[n];
        double[] axisMm = new double[n];
        List<Double> far = new ArrayList<>();
        for (int p = 0; p < n; p++) {
            Sample s = samples.get(p);
            double best = Double.POSITIVE_INFINITY;
            for (int r = 0; r < rays; r++) {
                double deg = r == 0 ? 0 : r % 2 == 1 ? ANGLES_DEG[(r + 1) / 2] : -ANGLES_DEG[(r + 1) / 2];
                dist[p][r] = geometry.beamDistanceMm(type, s.sensor(), s.gapMm(), s.objectRightDeg(), deg);
                best = StrictMath.min(best, dist[p][r]);
            }
            // The wall's angle off the axis: the beam that meets it nearest is the one along its normal.
            double h = type.sensor(s.sensor()).headingDeg();
            double off = StrictMath.abs(Math.IEEEremainder(-s.objectRightDeg() - h, 360));
            axisDeg[p] = off;
            axisMm[p] = best;
            if (best > DISTANCES_MM[nd - 1]) {
                far.add(s.counts());
            }
        }
        double offset = !Double.isNaN(fixedOffset) ? fixedOffset : far.isEmpty() ? 0 : median(far);
        double[] y = new double[n];
        for (int p = 0; p < n; p++) {
            y[p] = samples.get(p).counts() - offset;
        }
        double[][] t = start != null ? copy(start) : initial(axisDeg, axisMm, y);
        double[] gains = new double[sensors];
        Arrays.fill(gains, 1);
        int[] bestRay = new int[n];
        double[] m = new double[n];
        for (int pass = 0; pass < PASSES; pass++) {
            double[][] num = new double[na][nd];
            double[][] den = new double[na][nd];
            for (int p = 0; p < n; p++) {
                strongest(t, dist[p], p, bestRay, m);
                int s = samples.get(p).sensor();
                double pred = StrictMath.min(SampleTable.FULL_SCALE - offset, gains[s] * m[p]);
                double e = pred - y[p];
                if (bestRay[p] < 0 || (e > 0 == false && pred >= SampleTable.FULL_SCALE - offset)) {
                    continue;
                }
                int j = (bestRay[p] + 1) / 2;
                double d = dist[p][bestRay[p]];
                int c = cell(d);
                double w = (d - DISTANCES_MM[c]) / (DISTANCES_MM[c + 1] - DISTANCES_MM[c]);
                num[j][c] += e * gains[s] * (1 - w);
                den[j][c] += gains[s] * gains[s] * (1 - w) * (1 - w);
                num[j][c + 1] += e * gains[s] * w;
                den[j][c + 1] += gains[s] * gains[s] * w * w;
            }
            for (int j = 0; j < na; j++) {
                for (int c = 0; c < nd; c++) {
                    if (den[j][c] > 1e-9) {
                        t[j][c] -= 0.7 * num[j][c] / (den[j][c] + 1e-3);
                    }
                }
                falling(t[j]);
            }
            if (perSensorGains) {
                refitGains(t, dist, samples, y, offset, gains, bestRay, m);
            }
        }
        double[] resid0 = new double[n];
        List<Double> dark = new ArrayList<>();
        List<Double> rel = new ArrayList<>();
        for (int p = 0; p < n; p++) {
            strongest(t, dist[p], p, bestRay, m);
            double pred = gains[samples.get(p).sensor()] * m[p];
            resid0[p] = samples.get(p).counts() - offset - pred;
            if (pred < 1) {
                dark.add(StrictMath.abs(resid0[p]));
            } else if (pred > 100 && pred + offset < SampleTable.FULL_SCALE - 20) {
                rel.add(StrictMath.abs(resid0[p]) / pred);
            }
        }
        double noiseAbs = dark.isEmpty() ? 0 : 1.4826 * median(dark);
        double noiseRel = rel.isEmpty() ? 0 : StrictMath.min(1, 1.4826 * median(rel));
        return new Result(new Response.Table(DISTANCES_MM, ANGLES_DEG, t), gains, offset, noiseAbs, noiseRel);
    }

    private static double[][] copy(double[][] v) {
        double[][] c = new double[v.length][];
        for (int j = 0; j < v.length; j++) {
            c[j] = v[j].clone();
        }
        return c;
    }

    /** Bins the readings by their wall's angle off the axis and distance, and fills the gaps. */
    private static double[][] initial(double[] axisDeg, double[] axisMm, double[] y) {
        int nd = DISTANCES_MM.length;
        int na = ANGLES_DEG.length;
        double[][] sum = new double[na][nd];
        double[][] wt = new double[na][nd];
        for (int p = 0; p < y.length; p++) {
            if (axisMm[p] >= DISTANCES_MM[nd - 1] || axisDeg[p] > ANGLES_DEG[na - 1] + 5) {
                continue;
            }
            int j = (int) StrictMath.min(na - 1, StrictMath.rint(axisDeg[p] / 10));
            int c = cell(axisMm[p]);
            double w = (axisMm[p] - DISTANCES_MM[c]) / (DISTANCES_MM[c + 1] - DISTANCES_MM[c]);
            sum[j][c] += (1 - w) * y[p];
            wt[j][c] += 1 - w;
            sum[j][c + 1] += w * y[p];
            wt[j][c + 1] += w;
        }
        double[][] t = new double[na][nd];
        for (int j = 0; j < na; j++) {
            double last = j > 0 ? t[j - 1][0] * 0.7 : SampleTable.FULL_SCALE;
            for (int c = 0; c < nd; c++) {
                t[j][c] = wt[j][c] > 0.05 ? sum[j][c] / wt[j][c] : last;
                last = t[j][c];
            }
            falling(t[j]);
        }
        return t;
    }

    private static void strongest(double[][] t, double[] d, int p, int[] bestRay, double[] m) {
        double best = 0;
        int br = -1;
        double range = DISTANCES_MM[DISTANCES_MM.length - 1];
        for (int r = 0; r < d.length; r++) {
            if (d[r] <= range) {
                double v = at(t[(r + 1) / 2], d[r]);
                if (v > best || br < 0) {
                    best = v;
                    br = r;
                }
            }
        }
        bestRay[p] = br;
        m[p] = best;
    }

    private static void refitGains(double[][] t, double[][] dist, List<Sample> samples, double[] y, double offset,
            double[] gains, int[] bestRay, double[] m) {
        double[] sy = new double[gains.length];
        double[] sm = new double[gains.length];
        for (int p = 0; p < y.length; p++) {
            strongest(t, dist[p], p, bestRay, m);
            int s = samples.get(p).sensor();
            if (y[p] + offset < SampleTable.FULL_SCALE - 1) {
                sy[s] += y[p] * m[p];
                sm[s] += m[p] * m[p];
            }
        }
        double mean = 0;
        int k = 0;
        for (int s = 0; s < gains.length; s++) {
            if (sm[s] > 0) {
                gains[s] = StrictMath.max(0.05, sy[s] / sm[s]);
                mean += gains[s];
                k++;
            }
        }
        mean = k == 0 ? 1 : mean / k;
        for (int s = 0; s < gains.length; s++) {
            gains[s] /= mean;
        }
        for (double[] row : t) {
            for (int c = 0; c < row.length; c++) {
                row[c] *= mean;
            }
        }
    }

    /** Keeps a row within 0..1023, falling with distance (pool-adjacent-violators), and 0 at its end. */
    static void falling(double[] row) {
        int n = row.length;
        row[n - 1] = 0;
        double[] val = new double[n];
        int[] len = new int[n];
        int b = 0;
        for (int i = 0; i < n; i++) {
            val[b] = StrictMath.max(0, StrictMath.min(8 * SampleTable.FULL_SCALE, row[i]));
            len[b] = 1;
            while (b > 0 && val[b] > val[b - 1]) {
                val[b - 1] = (val[b - 1] * len[b - 1] + val[b] * len[b]) / (len[b - 1] + len[b]);
                len[b - 1] += len[b];
                b--;
            }
            b++;
        }
        int i = 0;
        for (int k = 0; k < b; k++) {
            for (int q = 0; q < len[k]; q++) {
                row[i++] = val[k];
            }
        }
        row[n - 1] = 0;
    }

    private static int cell(double d) {
        int c = 0;
        while (c + 2 < DISTANCES_MM.length && DISTANCES_MM[c + 1] < d) {
            c++;
        }
        return c;
    }

    private static double at(double[] row, double d) {
        int c = cell(d);
        double w = StrictMath.max(0,
                StrictMath.min(1, (d - DISTANCES_MM[c]) / (DISTANCES_MM[c + 1] - DISTANCES_MM[c])));
        return row[c] + w * (row[c + 1] - row[c]);
    }

    private static double median(List<Double> v) {
        double[] a = v.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return a.length % 2 == 1 ? a[a.length / 2] : (a[a.length / 2 - 1] + a[a.length / 2]) / 2;
    }
}
