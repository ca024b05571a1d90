package org.kheperasim.sim.engine;

/** Physical constants of the simulated Khepera I (khepera-reference.md, "Units and geometry"). */
public final class Khepera {
    /** Body radius: the Khepera I is about 55 mm across. */
    public static final double BODY_RADIUS_MM = 27.5;
    /** Distance between the wheels' contact points. */
    public static final double WHEEL_BASE_MM = 53.0;
    /** One speed unit is one pulse per 10 ms: 0.08 mm / 0.01 s. */
    public static final double MM_PER_S_PER_SPEED_UNIT = 8.0;
    /** The robot's motor controller period: motor noise is redrawn this often. */
    public static final long MOTOR_PERIOD_NANOS = 10_000_000L;

    private Khepera() {
    }
}
