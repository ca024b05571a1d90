package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.engine.robot.RobotType;

/**
 * Where each of the robot's sensors is in the arena, and which way it looks, for the robot's pose:
 * shared by the proximity and the light sensing.
 */
public final class SensorPlacement {
    /** How many sensors the robot has. */
    final int count;
    /** No sensor sits farther than this from the robot's centre, mm. */
    public final double reachMm;
    private final double[] localX;
    private final double[] localY;
    private final double[] localCos;
    private final double[] localSin;
    final double[] x;
    final double[] y;
    final double[] dx;
    final double[] dy;

    public SensorPlacement(RobotType type) {
        count = type.sensorCount();
        reachMm = type.sensorReachMm();
        localX = new double[count];
        localY = new double[count];
        localCos = new double[count];
        localSin = new double[count];
        x = new double[count];
        y = new double[count];
        dx = new double[count];
        dy = new double[count];
        for (int i = 0; i < count; i++) {
            RobotType.Sensor s = type.sensor(i);
            localX[i] = s.xMm();
            localY[i] = s.yMm();
            double h = StrictMath.toRadians(s.headingDeg());
            localCos[i] = StrictMath.cos(h);
            localSin[i] = StrictMath.sin(h);
        }
    }

    /** Place the sensors for a robot at (px, py) heading (c, s). */
    void place(double px, double py, double c, double s) {
        for (int i = 0; i < count; i++) {
            x[i] = px + c * localX[i] - s * localY[i];
            y[i] = py + s * localX[i] + c * localY[i];
            dx[i] = c * localCos[i] - s * localSin[i];
            dy[i] = s * localCos[i] + c * localSin[i];
        }
    }

    /** @return the reading for a model value: rounded and clamped to 0..1023 */
    static int reading(double v) {
        if (v <= 0) {
            return 0;
        }
        if (v >= 1023) {
            return 1023;
        }
        // v + 0.5 is positive here, so truncation is the floor (and much cheaper than StrictMath.floor).
        return (int) (v + 0.5);
    }

    /** @return the reading for a model value: rounded and clamped to 0..max */
    static int reading(double v, int max) {
        if (v <= 0) {
            return 0;
        }
        if (v >= max) {
            return max;
        }
        return (int) (v + 0.5);
    }

    /** @param reading a reading, 0..9999 @return how many decimal digits a reply writes for it */
    public static int digits(int reading) {
        return reading < 10 ? 1 : reading < 100 ? 2 : reading < 1000 ? 3 : 4;
    }
}
