package org.kheperasim.sim.engine.robot;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * What a calibration's series give beyond the wall fit ({@link Calibration}): each sensor's measured
 * noise from the raw repeats, a cap's and another robot's tables from their straight-ahead series, and
 * the light sensors' lamp response from the lamp series.
 */
final class CalibrationTables {
    private CalibrationTables() {
    }

    /**
     * The readings' spread, from the raw file's repeats at each wall point: with nothing in range (the
     * mean within 20 counts of the offset) the standard deviation is the sensor's noise in counts, on lit
     * readings (100..1000) the deviation over the signal its relative noise.
     *
     * @param csv the calibration's raw readings ({@code series,block,gap,heading,repeat,s0..})
     * @param sensors how many sensors
     * @param offset the reading with nothing in range
     * @return {@code {noiseAbs, noiseRel, scale_0 .. scale_n-1}}: the robot's noise and each sensor's over
     *     it; null when the file holds no repeats
     */
    static double[] noise(Path csv, int sensors, double offset) throws IOException {
        List<String> lines = Files.readAllLines(csv, StandardCharsets.UTF_8);
        List<List<Double>> dark = new ArrayList<>();
        List<Double> rel = new ArrayList<>();
        for (int i = 0; i < sensors; i++) {
            dark.add(new ArrayList<>());
        }
        List<int[]> group = new ArrayList<>();
        String key = null;
        for (int n = 1; n <= lines.size(); n++) {
            String[] f = n < lines.size() ? lines.get(n).split(",") : new String[0];
            String k = f.length > 4 && f[0].equals("wall") ? f[1] + "," + f[3] : null;
            if (key != null && !key.equals(k)) {
                spread(group, offset, dark, rel);
                group.clear();
            }
            key = k;
            if (k != null && f.length == 5 + sensors) {
                int[] v = new int[sensors];
                for (int i = 0; i < sensors; i++) {
                    v[i] = Integer.parseInt(f[5 + i].trim());
                }
                group.add(v);
            }
        }
        double[] each = new double[sensors];
        List<Double> all = new ArrayList<>();
        for (int i = 0; i < sensors; i++) {
            if (dark.get(i).isEmpty()) {
                return null;
            }
            each[i] = median(dark.get(i));
            all.add(each[i]);
        }
        double abs = median(all);
        double[] out = new double[2 + sensors];
        out[0] = abs;
        out[1] = rel.isEmpty() ? 0 : median(rel);
        for (int i = 0; i < sensors; i++) {
            out[2 + i] = abs > 0 ? StrictMath.min(100, each[i] / abs) : 1;
        }
        return out;
    }

    private static void spread(List<int[]> group, double offset, List<List<Double>> dark, List<Double> rel) {
        if (group.size() < 3) {
            return;
        }
        int sensors = group.get(0).length;
        for (int i = 0; i < sensors; i++) {
            double sum = 0;
            double sq = 0;
            for (int[] v : group) {
                sum += v[i];
                sq += (double) v[i] * v[i];
            }
            double mean = sum / group.size();
            double sd = StrictMath.sqrt(StrictMath.max(0, (sq - sum * mean) / (group.size() - 1)));
            if (mean <= offset + 20) {
                dark.get(i).add(sd);
            } else if (mean > 100 && mean < 1000) {
                rel.add(sd / (mean - offset));
            }
        }
    }

    /**
     * An object's table from its straight-ahead series: at each gap the front pair's signal over the wall
     * fit's there (how much it reflects at that distance), interpolated over the distance along the axis,
     * times the wall table; rows kept falling with distance.
     *
     * @param type the robot (its front pair: sensors 2 and 3 of a Khepera's 8, else the two facing most ahead)
     * @param fit the wall fit
     * @param gaps the series' gaps from the robot's front, mm
     * @param means its mean readings, {@code [gap][sensor]}
     * @return the object's table on the wall table's grid; null when the wall reads too little at those gaps
     */
    static Response.Table object(RobotType type, SampleFit.Result fit, double[] gaps, double[][] means) {
        int[] front = front(type);
        List<double[]> points = new ArrayList<>();
        for (int g = 0; g < gaps.length; g++) {
            List<Double> ratios = new ArrayList<>();
            double along = 0;
            for (int s : front) {
                double w = fit.predict(type, s, gaps[g], 0) - fit.offset();
                if (w > 50) {
                    ratios.add(StrictMath.max(0, means[g][s] - fit.offset()) / w);
                }
                RobotType.Sensor sn = type.sensor(s);
                along += type.body().radiusMm() + gaps[g] - sn.xMm();
            }
            if (!ratios.isEmpty()) {
                points.add(new double[] {along / front.length, median(ratios)});
            }
        }
        if (points.isEmpty()) {
            return null;
        }
        points.sort((a, b) -> Double.compare(a[0], b[0]));
        Response.Table wall = fit.table();
        double[] d = wall.distancesMm();
        double[][] v = wall.values();
        for (double[] row : v) {
            for (int c = 0; c < row.length; c++) {
                row[c] *= ratioAt(points, d[c]);
            }
            SampleFit.falling(row);
        }
        return new Response.Table(d, wall.anglesDeg(), v);
    }

    private static double ratioAt(List<double[]> p, double mm) {
        if (mm <= p.get(0)[0]) {
            return p.get(0)[1];
        }
        for (int k = 1; k < p.size(); k++) {
            if (mm <= p.get(k)[0]) {
                double t = (mm - p.get(k - 1)[0]) / (p.get(k)[0] - p.get(k - 1)[0]);
                return p.get(k - 1)[1] + t * (p.get(k)[1] - p.get(k - 1)[1]);
            }
        }
        return p.get(p.size() - 1)[1];
    }

    /**
     * The lamp series as the light sensors' response: the front pair's mean ambient reading {@code L} at
     * each distance as an activation {@code (dark - L) / (dark - bright)} (the type's levels), at the
     * sensors' distance from the lamp; beyond the last distance it fades linearly to 0 at twice it.
     *
     * @param type the robot
     * @param lampMm the series' distances from the robot's front, mm
     * @param means the mean ambient readings, {@code [distance][sensor]}
     * @return the lamp response; null without at least one distance
     */
    static LampResponse lamp(RobotType type, double[] lampMm, double[][] means) {
        if (lampMm.length == 0) {
            return null;
        }
        int[] front = front(type);
        double dark = type.light().dark();
        double bright = type.light().bright();
        double[][] p = new double[lampMm.length][];
        for (int k = 0; k < lampMm.length; k++) {
            double l = 0;
            double mm = 0;
            for (int s : front) {
                l += means[k][s] / front.length;
                mm += (type.body().radiusMm() + lampMm[k] - type.sensor(s).xMm()) / front.length;
            }
            p[k] = new double[] {mm, StrictMath.max(0, StrictMath.min(1, (dark - l) / (dark - bright)))};
        }
        Arrays.sort(p, (a, b) -> Double.compare(a[0], b[0]));
        double[] d = new double[p.length + 1];
        double[] a = new double[p.length + 1];
        for (int k = 0; k < p.length; k++) {
            d[k] = p[k][0];
            a[k] = p[k][1];
        }
        d[p.length] = 2 * p[p.length - 1][0];
        return new LampResponse(d, a);
    }

    /** @return the two sensors looking most nearly straight ahead */
    static int[] front(RobotType type) {
        Integer[] idx = new Integer[type.sensorCount()];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        Arrays.sort(idx, (a, b) -> Double.compare(StrictMath.abs(Math.IEEEremainder(type.sensor(a).headingDeg(), 360)),
                StrictMath.abs(Math.IEEEremainder(type.sensor(b).headingDeg(), 360))));
        return idx.length == 1 ? new int[] {idx[0]} : new int[] {StrictMath.min(idx[0], idx[1]),
            StrictMath.max(idx[0], idx[1])};
    }

    private static double median(List<Double> v) {
        double[] a = v.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return a.length % 2 == 1 ? a[a.length / 2] : (a[a.length / 2 - 1] + a[a.length / 2]) / 2;
    }
}
