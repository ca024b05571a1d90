package org.kheperasim.sim.engine;

import java.util.Arrays;
import java.util.List;

/**
 * A proximity sensor's response: reading against distance to a white wall, as a table interpolated
 * linearly. Beyond the last distance the response is zero (the sensor's offset and noise remain).
 *
 * @param name the profile's name, used in settings
 * @param distancesMm increasing distances from the sensor, mm
 * @param values readings at those distances, before offset and noise
 */
public record ProximityProfile(String name, double[] distancesMm, double[] values) {

    /**
     * The default, for the paper's Khepera I: about 1000 within a few mm of a white wall, 600 at
     * 20 mm (the Appendix controller's threshold), falling to nothing by 60 mm; the sensor's
     * offset puts a noise floor of a few tens beyond 50 mm (khepera-reference.md, "Default sensor
     * profile").
     */
    public static final ProximityProfile KHEPERA_I = new ProximityProfile("khepera1",
            new double[] {0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60},
            new double[] {1023, 985, 880, 745, 600, 455, 325, 215, 130, 70, 30, 10, 0});

    /**
     * The Khepera II white-sheet calibration (RoadNarrows' default, taken "placing a sheet of white
     * paper at various distances", Khepera manual section 3.1.8): 1000 at 10 mm, 450 at 20 mm, 80 at
     * 100 mm. Those are whole readings, the sensor's residual included, so the table holds them less
     * the nominal offset ({@code prox.offset}, 15) that every reading adds: a robot's mean reading
     * at each distance is the published one. Beyond 100 mm the response falls to nothing by 120 mm.
     */
    public static final ProximityProfile KHEPERA_II = new ProximityProfile("khepera2",
            new double[] {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 120},
            new double[] {1008, 985, 435, 260, 175, 135, 110, 95, 85, 75, 65, 0});


    /** The built-in profiles, by name. */
    public static final List<ProximityProfile> BUILT_IN = List.of(KHEPERA_I, KHEPERA_II);

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
            throw new IllegalArgumentException("profile " + name + ": the last distance, the sensors' range, must be at least "
                    + MIN_RANGE_MM + " mm, not " + distancesMm[distancesMm.length - 1]);
        }
        distancesMm = distancesMm.clone();
        values = values.clone();
    }

    /** The shortest range a profile may have, mm (see the check above). */
    public static final double MIN_RANGE_MM = 1;

    /** @param name a profile name @return the built-in profile of that name */
    public static ProximityProfile named(String name) {
        for (ProximityProfile p : BUILT_IN) {
            if (p.name.equals(name)) {
                return p;
            }
        }
        throw new IllegalArgumentException("unknown proximity profile '" + name + "'; use one of "
                + BUILT_IN.stream().map(ProximityProfile::name).toList());
    }

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
        int i = 1;
        while (distancesMm[i] < distanceMm) {
            i++;
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
