package org.kheperasim.sim.engine.robot;

import java.util.Arrays;

/**
 * A proximity sensor's response over the distance to a white wall and the angle off the sensor's
 * axis. The engine casts one beam along the axis and a pair at plus and minus each further angle
 * ({@link #anglesDeg}), and weighs what a beam meets by {@link #weight} times {@link #along}.
 *
 * <p>Two forms: a {@link Curve} (one distance profile, scaled by a weight per angle: today's
 * Khepera curves) or a {@link Table} (a value for every distance and angle, interpolated linearly
 * over the distance; between its angles, {@link #valueAt} interpolates over the angle too).
 */
public sealed interface Response permits Response.Curve, Response.Table {

    /** @return the beam angles off the axis, degrees, from 0 upward (0 first) */
    double[] anglesDeg();

    /** @param angle an index into {@link #anglesDeg} @return the response along the beams at that angle */
    ProximityProfile along(int angle);

    /** @param angle an index into {@link #anglesDeg} @return the weight of the beams at that angle */
    double weight(int angle);

    /** @return the farthest distance with a response, mm: the sensor's range */
    double rangeMm();

    /**
     * @return the largest response of any beam at any distance, counts before the offset: what an
     *     obstacle at the best distance along the best beam gives (a reading is the beams' largest)
     */
    default double peak() {
        double best = 0;
        for (int j = 0; j < anglesDeg().length; j++) {
            for (double v : along(j).values()) {
                best = StrictMath.max(best, weight(j) * v);
            }
        }
        return best;
    }

    /**
     * @param distanceMm distance to a white wall, mm
     * @param angleDeg angle off the sensor's axis, degrees (its sign does not matter)
     * @return the reading before gain, offset and noise, interpolated; 0 beyond the largest angle
     */
    default double valueAt(double distanceMm, double angleDeg) {
        double[] a = anglesDeg();
        double x = StrictMath.abs(angleDeg);
        if (x > a[a.length - 1]) {
            return 0;
        }
        int j = 0;
        while (j + 1 < a.length && a[j + 1] < x) {
            j++;
        }
        double here = weight(j) * along(j).valueAt(distanceMm);
        if (j + 1 >= a.length || x <= a[j]) {
            return here;
        }
        double t = (x - a[j]) / (a[j + 1] - a[j]);
        return here + t * (weight(j + 1) * along(j + 1).valueAt(distanceMm) - here);
    }

    /**
     * One distance profile for every beam, each angle's beams weighted.
     *
     * @param distance the response along the axis
     * @param anglesDeg beam angles, from 0 upward
     * @param weights one weight for each angle
     */
    record Curve(ProximityProfile distance, double[] anglesDeg, double[] weights) implements Response {
        public Curve {
            checkAngles(anglesDeg, weights.length, "weights");
            anglesDeg = anglesDeg.clone();
            weights = weights.clone();
        }

        @Override
        public double[] anglesDeg() {
            return anglesDeg.clone();
        }

        @Override
        public double[] weights() {
            return weights.clone();
        }

        @Override
        public ProximityProfile along(int angle) {
            return distance;
        }

        @Override
        public double weight(int angle) {
            return weights[angle];
        }

        @Override
        public double rangeMm() {
            return distance.rangeMm();
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Curve c && c.distance.equals(distance) && Arrays.equals(c.anglesDeg, anglesDeg)
                    && Arrays.equals(c.weights, weights);
        }

        @Override
        public int hashCode() {
            return distance.hashCode() * 31 + Arrays.hashCode(weights);
        }
    }

    /**
     * A value for every distance and angle (measured, say): the beams at each angle follow that
     * angle's row, weight 1.
     *
     * @param distancesMm increasing distances, mm
     * @param anglesDeg beam angles, from 0 upward
     * @param values {@code values[angle][distance]}, each row falling (or level) with distance
     */
    record Table(double[] distancesMm, double[] anglesDeg, double[][] values) implements Response {
        public Table {
            checkAngles(anglesDeg, values.length, "rows");
            ProximityProfile[] rows = new ProximityProfile[values.length];
            for (int j = 0; j < values.length; j++) {
                rows[j] = new ProximityProfile("table@" + anglesDeg[j], distancesMm, values[j]);
                for (int i = 1; i < values[j].length; i++) {
                    if (values[j][i] > values[j][i - 1]) {
                        throw new IllegalArgumentException("the table's row for " + anglesDeg[j]
                                + " degrees rises with distance (" + values[j][i - 1] + " then " + values[j][i]
                                + "): a proximity response must fall or stay level as the wall moves away");
                    }
                }
            }
            distancesMm = distancesMm.clone();
            anglesDeg = anglesDeg.clone();
            double[][] copy = new double[values.length][];
            for (int j = 0; j < values.length; j++) {
                copy[j] = values[j].clone();
            }
            values = copy;
        }

        @Override
        public double[] anglesDeg() {
            return anglesDeg.clone();
        }

        @Override
        public double[] distancesMm() {
            return distancesMm.clone();
        }

        @Override
        public double[][] values() {
            double[][] copy = new double[values.length][];
            for (int j = 0; j < values.length; j++) {
                copy[j] = values[j].clone();
            }
            return copy;
        }

        @Override
        public ProximityProfile along(int angle) {
            return new ProximityProfile("table@" + anglesDeg[angle], distancesMm, values[angle]);
        }

        @Override
        public double weight(int angle) {
            return 1;
        }

        @Override
        public double rangeMm() {
            return distancesMm[distancesMm.length - 1];
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Table t && Arrays.equals(t.distancesMm, distancesMm)
                    && Arrays.equals(t.anglesDeg, anglesDeg)
                    && Arrays.deepEquals(t.values, values);
        }

        @Override
        public int hashCode() {
            return Arrays.hashCode(distancesMm) * 31 + Arrays.deepHashCode(values);
        }
    }

    private static void checkAngles(double[] anglesDeg, int count, String what) {
        if (anglesDeg.length == 0 || anglesDeg[0] != 0) {
            throw new IllegalArgumentException("the beam angles must start at 0 (the sensor's axis), not "
                    + Arrays.toString(anglesDeg));
        }
        for (int j = 1; j < anglesDeg.length; j++) {
            if (!(anglesDeg[j] > anglesDeg[j - 1]) || anglesDeg[j] >= 90) {
                throw new IllegalArgumentException("the beam angles must increase and stay below 90 degrees, not "
                        + Arrays.toString(anglesDeg));
            }
        }
        if (count != anglesDeg.length) {
            throw new IllegalArgumentException(anglesDeg.length + " beam angles but " + count + " " + what
                    + ": give one for each angle");
        }
    }
}
