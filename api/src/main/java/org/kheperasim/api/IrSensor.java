package org.kheperasim.api;

/**
 * The eight infrared sensors of the Khepera, in the robot's own index order (the order of the
 * {@code N} and {@code O} replies). Each sensor measures both proximity (reflected IR) and ambient
 * light.
 *
 * <p>Mounting poses are in the robot frame: x forward, y to the left, millimetres from the centre
 * of the robot; the heading is the direction the sensor looks, in degrees counter-clockwise from
 * straight ahead.
 */
public enum IrSensor {
    /** Index 0: looks left (90°). */
    LEFT_90(0, 10, 24, 90),
    /** Index 1: looks front-left (45°). */
    LEFT_45(1, 19, 17, 45),
    /** Index 2: looks ahead, mounted left of centre. */
    FRONT_LEFT(2, 25, 6, 0),
    /** Index 3: looks ahead, mounted right of centre. */
    FRONT_RIGHT(3, 25, -6, 0),
    /** Index 4: looks front-right (−45°). */
    RIGHT_45(4, 19, -17, -45),
    /** Index 5: looks right (−90°). */
    RIGHT_90(5, 10, -24, -90),
    /** Index 6: looks back, mounted right of centre. */
    BACK_RIGHT(6, -24, -10, 180),
    /** Index 7: looks back, mounted left of centre. */
    BACK_LEFT(7, -24, 10, 180);

    /** Number of IR sensors on a Khepera. */
    public static final int COUNT = 8;

    private final int index;
    private final double xMm;
    private final double yMm;
    private final double headingDeg;

    IrSensor(int index, double xMm, double yMm, double headingDeg) {
        this.index = index;
        this.xMm = xMm;
        this.yMm = yMm;
        this.headingDeg = headingDeg;
    }

    /** @return the sensor's index, 0..7, as used by {@code sensors[i]} */
    public int index() {
        return index;
    }

    /** @return mounting position forward of the robot's centre, mm */
    public double xMm() {
        return xMm;
    }

    /** @return mounting position to the left of the robot's centre, mm */
    public double yMm() {
        return yMm;
    }

    /** @return viewing direction, degrees counter-clockwise from straight ahead */
    public double headingDeg() {
        return headingDeg;
    }

    /**
     * @param index 0..7
     * @return the sensor with that index
     * @throws IllegalArgumentException if the index is outside 0..7
     */
    public static IrSensor of(int index) {
        if (index < 0 || index >= COUNT) {
            throw new IllegalArgumentException(
                    "IR sensor index " + index + " does not exist: the Khepera has sensors 0..7");
        }
        return values()[index];
    }
}
