package org.kheperasim.sim.engine;

import org.kheperasim.api.IrSensor;

/**
 * Where each of the eight sensors is in the arena, and which way it looks, for the robot's pose:
 * shared by the proximity and the light sensing.
 */
final class SensorPlacement {
    /** No sensor sits farther than this from the robot's centre, mm. */
    static final double REACH_MM = 26.5;

    private final double[] localX = new double[IrSensor.COUNT];
    private final double[] localY = new double[IrSensor.COUNT];
    private final double[] localCos = new double[IrSensor.COUNT];
    private final double[] localSin = new double[IrSensor.COUNT];
    final double[] x = new double[IrSensor.COUNT];
    final double[] y = new double[IrSensor.COUNT];
    final double[] dx = new double[IrSensor.COUNT];
    final double[] dy = new double[IrSensor.COUNT];

    SensorPlacement() {
        for (IrSensor s : IrSensor.values()) {
            int i = s.index();
            localX[i] = s.xMm();
            localY[i] = s.yMm();
            double h = StrictMath.toRadians(s.headingDeg());
            localCos[i] = StrictMath.cos(h);
            localSin[i] = StrictMath.sin(h);
        }
    }

    /** Place the sensors for a robot at (px, py) heading (c, s). */
    void place(double px, double py, double c, double s) {
        for (int i = 0; i < IrSensor.COUNT; i++) {
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

    /** @param reading a reading, 0..1023 @return how many decimal digits a reply writes for it */
    static int digits(int reading) {
        return reading < 10 ? 1 : reading < 100 ? 2 : reading < 1000 ? 3 : 4;
    }
}
