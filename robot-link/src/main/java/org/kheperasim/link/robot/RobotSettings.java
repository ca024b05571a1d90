package org.kheperasim.link.robot;

import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.dialect.Dialect;

/**
 * How the robot backend drives the robot.
 *
 * @param maxSpeed the speed clamp: wheel speeds a controller asks for are limited to ±maxSpeed
 *     speed units (≈ 8 mm/s each) before they are sent
 * @param gripper whether a gripper turret is fitted: its state is polled and its commands are sent
 * @param parkGripperOnStop on stop, open the fingers and raise the arm (then stop the wheels again)
 * @param armUp arm position sent for {@code UP}, 0..255 (larger = lower)
 * @param armDown arm position sent for {@code DOWN}
 * @param armTravelMillis how long the arm takes between up and down, ms (the robot does not say)
 * @param options settings a controller style consults ({@code RobotPort.option}), e.g.
 *     {@code wsu.positionUnits=legacy} for WSU controllers whose wheel positions count as in the original
 */
public record RobotSettings(int maxSpeed, boolean gripper, boolean parkGripperOnStop, int armUp, int armDown,
        long armTravelMillis, java.util.Map<String, String> options) {

    /**
     * The WSU API's wheel-position unit ({@code pulses} or {@code legacy}), as the simulator's setting of the same
     * name.
     */
    public static final String WSU_POSITION_UNITS = "wsu.positionUnits";
    /**
     * The system property that sets {@value #WSU_POSITION_UNITS} for a run
     * ({@code java -Dkheperasim.wsu.positionUnits=legacy -jar khepera-link.jar run ...}).
     */
    public static final String WSU_POSITION_UNITS_PROPERTY = "kheperasim." + WSU_POSITION_UNITS;

    /** The WSU API's speed unit ({@code khepera} or {@code legacy}), as the simulator's setting of the same name. */
    public static final String WSU_SPEED_UNITS = "wsu.speedUnits";
    /** The system property that sets {@value #WSU_SPEED_UNITS} for a run. */
    public static final String WSU_SPEED_UNITS_PROPERTY = "kheperasim." + WSU_SPEED_UNITS;

    /** The default speed clamp: 20 units ≈ 16 cm/s, well below the robot's 127. */
    public static final int DEFAULT_MAX_SPEED = 20;

    /** Checks the values. */
    public RobotSettings {
        options = java.util.Map.copyOf(options);
        if (maxSpeed < 0 || maxSpeed > EpuckCommand.MAX_SPEED) {
            throw new IllegalArgumentException("--max-speed " + maxSpeed + " must lie in 0..127 speed units"
                    + " (1 unit is about 8 mm/s; an e-puck takes 0..1000 steps/s)");
        }
        if (armUp < 0 || armUp > 255 || armDown < 0 || armDown > 255) {
            throw new IllegalArgumentException("arm positions " + armUp + " / " + armDown + " must lie in 0..255");
        }
    }

    /**
     * @return clamp 20, no gripper; {@value #WSU_POSITION_UNITS} and {@value #WSU_SPEED_UNITS} from the
     *     system properties {@value #WSU_POSITION_UNITS_PROPERTY} and {@value #WSU_SPEED_UNITS_PROPERTY}
     *     when they are set
     */
    public static RobotSettings defaults() {
        java.util.Map<String, String> options = new java.util.TreeMap<>();
        for (String key : new String[] {WSU_POSITION_UNITS, WSU_SPEED_UNITS}) {
            String value = System.getProperty("kheperasim." + key);
            if (value != null) {
                options.put(key, value);
            }
        }
        return new RobotSettings(DEFAULT_MAX_SPEED, false, false, 180, 249, 1000, options);
    }

    /** @param units the clamp @return these settings with it */
    public RobotSettings withMaxSpeed(int units) {
        return new RobotSettings(units, gripper, parkGripperOnStop, armUp, armDown, armTravelMillis, options);
    }

    /** @param fitted gripper fitted @param park park it on stop @return these settings with them */
    public RobotSettings withGripper(boolean fitted, boolean park) {
        return new RobotSettings(maxSpeed, fitted, park, armUp, armDown, armTravelMillis, options);
    }

    /** @param key an option's name @param value its value @return these settings with it */
    public RobotSettings withOption(String key, String value) {
        java.util.Map<String, String> next = new java.util.TreeMap<>(options);
        next.put(key, value);
        return new RobotSettings(maxSpeed, gripper, parkGripperOnStop, armUp, armDown, armTravelMillis, next);
    }

    /**
     * @param dialect the robot's protocol
     * @return these settings, when the speed clamp and the gripper fit the robot
     * @throws IllegalArgumentException naming the value and the robot's range
     */
    public RobotSettings checkFor(Dialect dialect) {
        if (maxSpeed > dialect.maxSpeed()) {
            throw new IllegalArgumentException("--max-speed " + maxSpeed + " is above the " + dialect.robot() + "'s "
                    + dialect.maxSpeed() + " (--dialect " + dialect.name() + "); give 0.." + dialect.maxSpeed());
        }
        if (gripper && !dialect.turrets()) {
            throw new IllegalArgumentException("--gripper: the " + dialect.robot() + " (--dialect " + dialect.name()
                    + ") takes no turret; leave --gripper out");
        }
        return this;
    }
}
