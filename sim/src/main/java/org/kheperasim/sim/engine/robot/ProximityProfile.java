package org.kheperasim.sim.engine.robot;

import java.util.Arrays;

/**
 * A proximity sensor's response along one beam: reading against distance to a white wall, as a
 * table interpolated linearly (the robots' own tables are in their {@link RobotType}). Beyond the last distance the
 * response is zero (the sensor's offset and noise remain).
 *
 * @param name the profile's name, used in settings
 * @param distancesMm increasing distances from the sensor, mm
 * @param values readings at those distances, before offset and noise
 */
public record ProximityProfile(String name, double[] distancesMm, double[] values) {

    /** Checks the table. */
    public ProximityProfile {
        if (distancesMm.length != values.length || distancesMm.length < 2) {
            throw new IllegalArgumentException("profile " + name + ": distances and values must pair up, two at least");
        }
        for (int i = 1; i < distancesMm.length; i++) {
            if (!(distancesMm[i] > distancesMm[i - 1])) {
                throw new IllegalArgumentException("profile " + name + ": distances must increase");
            }
        }
        if (!(distancesMm[distancesMm.length - 1] >= MIN_RANGE_MM)) {
            // Crowd joins robots that may touch within a stretch into one unit, and a sample of each
            // sees the others only because they are then within its sight: that takes a range of a
            // fraction of a millimetre at least; 1 mm leaves room.
            throw new IllegalArgumentException("profile " + name
                    + ": the last distance, the sensors' range, must be at least "
                    + MIN_RANGE_MM + " mm, not " + distancesMm[distancesMm.length - 1]);
        }
        distancesMm = distancesMm.clone();
        values = values.clone();
    }

    /** The shortest range a profile may have, mm (see the check above). */
    public static final double MIN_RANGE_MM = 1;

    /** @return the farthest distance with a non-zero response, mm */
    public double rangeMm() {
        return distancesMm[distancesMm.length - 1];
    }

    /**
     * The distance beyond which the response is at most {@code v}: {@code valueAt(d) <= v} for every
     * d past it (the profile falls with distance).
     *
     * @param v a response value
     * @return distance, mm (0 when even contact gives no more than v)
     */
    public double distanceBeyondWhichAtMost(double v) {
        if (values[0] <= v) {
            return 0;
        }
        for (int i = 1; i < values.length; i++) {
            if (values[i] <= v) {
                double t = (values[i - 1] - v) / (values[i - 1] - values[i]);
                return distancesMm[i - 1] + t * (distancesMm[i] - distancesMm[i - 1]);
            }
        }
        return distancesMm[distancesMm.length - 1];
    }

    /** @param distanceMm distance from the sensor to the reflecting surface, mm @return the reading */
    public double valueAt(double distanceMm) {
        if (distanceMm <= distancesMm[0]) {
            return values[0];
        }
        int n = distancesMm.length;
        if (distanceMm >= distancesMm[n - 1]) {
            return values[n - 1];
        }
        // The first distance not below distanceMm: from where an even table would have it, then exactly.
        double first = distancesMm[0];
        double even = (distanceMm - first) * (n - 1) / (distancesMm[n - 1] - first);
        int i = (int) StrictMath.min(n - 1, StrictMath.max(1, even));
        while (distancesMm[i] < distanceMm) {
            i++;
        }
        while (i > 1 && distancesMm[i - 1] >= distanceMm) {
            i--;
        }
        double t = (distanceMm - distancesMm[i - 1]) / (distancesMm[i] - distancesMm[i - 1]);
        return values[i - 1] + t * (values[i] - values[i - 1]);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ProximityProfile p && p.name.equals(name)
                && Arrays.equals(p.distancesMm, distancesMm) && Arrays.equals(p.values, values);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + Arrays.hashCode(distancesMm);
    }

    @Override
    public String toString() {
        return name;
    }
}
