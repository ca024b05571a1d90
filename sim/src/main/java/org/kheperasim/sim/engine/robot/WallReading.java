package org.kheperasim.sim.engine.robot;

/**
 * What a robot's proximity sensor reads from a straight white wall, by the engine's beam rule: the
 * sensor casts its beams (the axis and a pair at plus and minus each further angle of its
 * {@link Response}), each meets the wall at some distance along it, and the strongest beam's
 * response is the reading, before gain, offset and noise. Used to fit measured tables and to compare
 * a response with a real robot's readings without building an arena.
 *
 * <p>The wall's nearest point lies {@code objectRightDeg} degrees to the robot's right of straight
 * ahead, {@code gapMm} from the body's surface (the layout of the sampled tables, {@link SampleTable}).
 */
public final class WallReading {
    private WallReading() {
    }

    /**
     * @param type the robot (body radius, sensor poses)
     * @param sensor a sensor index
     * @param gapMm the wall's distance from the body's surface, mm
     * @param objectRightDeg where the wall's nearest point lies, degrees to the right of ahead
     * @param beamDeg a beam's angle off the sensor's axis, degrees counter-clockwise
     * @return the distance along that beam to the wall, mm; infinity if the beam runs away from it
     */
    public static double beamDistanceMm(RobotType type, int sensor, double gapMm, double objectRightDeg,
            double beamDeg) {
        RobotType.Sensor s = type.sensor(sensor);
        double th = StrictMath.toRadians(objectRightDeg);
        double ux = StrictMath.cos(th);
        double uy = -StrictMath.sin(th);
        double perpendicular = type.body().radiusMm() + gapMm - (s.xMm() * ux + s.yMm() * uy);
        double cos = StrictMath.cos(StrictMath.toRadians(s.headingDeg() + beamDeg) + th);
        if (cos <= 1e-9 || perpendicular < 0) {
            return Double.POSITIVE_INFINITY;
        }
        return perpendicular / cos;
    }

    /**
     * @param type the robot
     * @param response the proximity response
     * @param sensor a sensor index
     * @param gapMm the wall's distance from the body's surface, mm
     * @param objectRightDeg where the wall lies, degrees to the right of ahead
     * @return the strongest beam's response, before gain, offset and noise
     */
    public static double raw(RobotType type, Response response, int sensor, double gapMm, double objectRightDeg) {
        double[] a = response.anglesDeg();
        double range = response.rangeMm();
        double best = 0;
        for (int j = 0; j < a.length; j++) {
            for (int sign = j == 0 ? 1 : -1; sign <= 1; sign += 2) {
                double d = beamDistanceMm(type, sensor, gapMm, objectRightDeg, sign * a[j]);
                if (d <= range) {
                    best = StrictMath.max(best, response.weight(j) * response.along(j).valueAt(d));
                }
            }
        }
        return best;
    }

    /**
     * @return the reading without noise: {@code gain * raw + offset}, clipped to 0..1023
     * @param type the robot
     * @param response the proximity response
     * @param sensor a sensor index
     * @param gain the sensor's gain
     * @param offset the reading with nothing in range, counts
     * @param gapMm the wall's distance from the body's surface, mm
     * @param objectRightDeg where the wall lies, degrees to the right of ahead
     */
    public static double reading(RobotType type, Response response, int sensor, double gain,
            double offset, double gapMm,
            double objectRightDeg) {
        double v = gain * raw(type, response, sensor, gapMm, objectRightDeg) + offset;
        return StrictMath.max(0, StrictMath.min(SampleTable.FULL_SCALE, v));
    }
}
