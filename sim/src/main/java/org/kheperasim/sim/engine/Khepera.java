package org.kheperasim.sim.engine;

/** Physical constants of the simulated Khepera I (khepera-reference.md, "Units and geometry"). */
public final class Khepera {
    /** Body radius: the Khepera I is about 55 mm across. */
    public static final double BODY_RADIUS_MM = 27.5;
    /** Distance between the wheels' contact points. */
    public static final double WHEEL_BASE_MM = 53.0;
    /** One speed unit is one pulse per 10 ms: 0.08 mm / 0.01 s. */
    public static final double MM_PER_S_PER_SPEED_UNIT = 8.0;
    /** The robot's motor controller period: position moves are updated this often. */
    public static final long MOTOR_PERIOD_NANOS = 10_000_000L;
    /**
     * How often each wheel's speed noise is redrawn. A real wheel's speed error under its PID comes
     * from slip and gear play, which vary over millimetres of travel (2 mm in 50 ms at 40 mm/s),
     * not at the controller's 100 Hz; see docs/simulation-model.md for the choice.
     */
    public static final long MOTOR_NOISE_PERIOD_NANOS = 50_000_000L;

    private Khepera() {
    }
}
