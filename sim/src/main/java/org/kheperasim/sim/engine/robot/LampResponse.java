package org.kheperasim.sim.engine.robot;

import java.util.Arrays;

/**
 * A light sensor's measured response to a lamp: how lit it is (0 dark, 1 the brightest reading) with the
 * lamp straight ahead at a distance, interpolated linearly and 0 beyond the last distance. It takes the
 * place of the engine's modelled fall-off ({@code (1 - r / range)^2}) for a measured robot: a lamp then
 * lights a sensor by its intensity, times how squarely the sensor faces it, times this.
 *
 * <p>A calibration's lamp series gives it from the robot's ambient readings {@code L} by
 * {@code activation = (dark - L) / (dark - bright)}, the inverse of the engine's
 * {@code reading = dark - (dark - bright) * exposure}; a sampled light table (evorobotpy's
 * {@code .sample}, whose activations already rise with the light) gives it directly
 * ({@link SampleTable#ambientReading} states the transform).
 *
 * @param distancesMm increasing distances from the sensor to the lamp, mm
 * @param activations how lit the sensor is there, 0..1
 */
public record LampResponse(double[] distancesMm, double[] activations) {
    public LampResponse {
        if (distancesMm.length != activations.length || distancesMm.length < 2) {
            throw new IllegalArgumentException("a lamp response needs two distances at least, each with an activation");
        }
        for (int i = 0; i < distancesMm.length; i++) {
            if (i > 0 && !(distancesMm[i] > distancesMm[i - 1])) {
                throw new IllegalArgumentException("the lamp response's distances must increase, not "
                        + Arrays.toString(distancesMm));
            }
            if (!(activations[i] >= 0 && activations[i] <= 1)) {
                throw new IllegalArgumentException("a lamp activation is 0..1 (0 dark, 1 the brightest), not "
                        + activations[i]);
            }
        }
        distancesMm = distancesMm.clone();
        activations = activations.clone();
    }

    @Override
    public double[] distancesMm() {
        return distancesMm.clone();
    }

    @Override
    public double[] activations() {
        return activations.clone();
    }

    /** @param mm the sensor's distance from the lamp, mm @return its activation there, 0 beyond the last distance */
    public double activation(double mm) {
        int n = distancesMm.length;
        if (mm <= distancesMm[0]) {
            return activations[0];
        }
        if (mm > distancesMm[n - 1]) {
            return 0;
        }
        int i = 1;
        while (distancesMm[i] < mm) {
            i++;
        }
        double t = (mm - distancesMm[i - 1]) / (distancesMm[i] - distancesMm[i - 1]);
        return activations[i - 1] + t * (activations[i] - activations[i - 1]);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof LampResponse l && Arrays.equals(l.distancesMm, distancesMm)
                && Arrays.equals(l.activations, activations);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(distancesMm) * 31 + Arrays.hashCode(activations);
    }
}
