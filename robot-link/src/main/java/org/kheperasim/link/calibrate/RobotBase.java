package org.kheperasim.link.calibrate;

import org.kheperasim.link.protocol.dialect.Dialect;

/**
 * The nominal numbers of the robot a calibration measures, the ones the procedure starts from before it
 * has measured its own: how many sensors it reads, their full scale, the encoders' travel per pulse and
 * the wheel base (the spin's pulses for one nominal turn, the questions' defaults). They are the bundled
 * robot type's of the same name ({@code khepera1}, {@code khepera2}; the simulator's robot files hold
 * them, and a test checks these against them); the calibration file names that type as its base.
 *
 * @param name the robot type the calibration overlays
 * @param sensors how many infrared sensors it has
 * @param fullScale the largest proximity reading, counts
 * @param mmPerPulse nominal wheel travel per encoder pulse, mm
 * @param wheelBaseMm nominal wheel base, mm
 */
public record RobotBase(String name, int sensors, int fullScale, double mmPerPulse, double wheelBaseMm) {
    /** The Khepera I's: 8 sensors of 10 bits, 0.08 mm a pulse, 53 mm between the wheels (K-Team manual). */
    public static final RobotBase KHEPERA1 = new RobotBase("khepera1", 8, 1023, 0.08, 53);
    /** The Khepera II's: the same numbers (Khepera II manual; the bundled khepera2 robot file). */
    public static final RobotBase KHEPERA2 = new RobotBase("khepera2", 8, 1023, 0.08, 53);

    /**
     * @param d the robot's protocol
     * @return the robot that speaks it
     * @throws IllegalArgumentException naming what the procedure lacks for that robot
     */
    public static RobotBase of(Dialect d) {
        return switch (d.name()) {
            case "khepera1" -> KHEPERA1;
            case "khepera2" -> KHEPERA2;
            default -> throw new IllegalArgumentException("--dialect " + d.name() + ": calibrate cannot measure the "
                    + d.robot() + " yet: it moves the robot by position commands (C, which the " + d.robot()
                    + " lacks: it has speeds and step counters only), and the " + d.robot() + "'s sensor scale"
                    + " (12 bits) and step size (0.1288 mm) are not in its procedure; calibrate a Khepera"
                    + " (--dialect khepera1 or khepera2)");
        };
    }

    /** @return the pulses per wheel of a spin on the spot through one nominal turn */
    public int turnPulses() {
        return (int) StrictMath.rint(StrictMath.PI * wheelBaseMm / mmPerPulse);
    }
}
