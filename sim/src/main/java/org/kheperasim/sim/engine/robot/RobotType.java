package org.kheperasim.sim.engine.robot;

import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * Everything that makes one kind of robot: its body, its wheels, its infrared sensors (each measures
 * both proximity and ambient light, as on the Khepera and the e-puck), the turrets it carries and
 * the protocol dialect it speaks. The engine, the window, the web page, the protocol server, the
 * trace and the testing module read a robot's numbers from here and nowhere else; a robot file
 * ({@code docs/robot-files.md}) holds one, and {@link RobotTypes} the bundled ones.
 *
 * <p>Robot frame: x forward, y to the left, mm from the centre; headings in degrees
 * counter-clockwise from straight ahead.
 *
 * @param name the type's name ({@code khepera1}, {@code epuck}, ...)
 * @param source where its numbers come from (a manual, a published model), one line
 * @param body the body
 * @param drive the wheels and their motor controller
 * @param sensors the infrared sensors, in the order a controller indexes them
 * @param proximity how the sensors answer to reflected infrared
 * @param light how the sensors answer to ambient light
 * @param turrets the turrets it carries
 * @param dialect the name of the serial protocol it speaks ({@code khepera1}, {@code khepera2}, {@code epuck})
 * @param measured what a calibration measured on one robot of the kind (its sensors' gains, its wheels'
 *     spread), or null for a kind of robot: then each run draws a robot of the kind ({@code prox.gainSpread} ...)
 */
public record RobotType(String name, String source, Body body, Drive drive, List<Sensor> sensors, Proximity proximity,
        Light light, Set<Turret> turrets, String dialect, Measured measured) {

    /** The slack {@link #sensorReachMm} leaves beyond the farthest sensor, mm. */
    private static final double REACH_SLACK_MM = 0.5;

    public RobotType {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(body, "body");
        Objects.requireNonNull(drive, "drive");
        Objects.requireNonNull(proximity, "proximity");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(dialect, "dialect");
        sensors = List.copyOf(sensors);
        turrets = Set.copyOf(turrets);
        if (sensors.isEmpty()) {
            throw new IllegalArgumentException("robot " + name + " has no sensors: give one at least");
        }
        if (measured != null && measured.proxGains().size() != sensors.size()) {
            throw new IllegalArgumentException("robot " + name + " has " + sensors.size()
                    + " sensors but its calibration "
                    + measured.proxGains().size() + " gains: give one gain a sensor");
        }
        if (measured != null) {
            measured.tables().check(name, sensors.size());
        }
    }

    /** A kind of robot, not one measured robot ({@link #measured()} null). */
    public RobotType(String name, String source, Body body, Drive drive, List<Sensor> sensors, Proximity proximity,
            Light light, Set<Turret> turrets, String dialect) {
        this(name, source, body, drive, sensors, proximity, light, turrets, dialect, null);
    }

    /** @return how many infrared sensors it has */
    public int sensorCount() {
        return sensors.size();
    }

    /** @param i a sensor index @return that sensor */
    public Sensor sensor(int i) {
        return sensors.get(i);
    }

    /** @return a bound on every sensor's distance from the centre, mm (the farthest, plus half a millimetre) */
    public double sensorReachMm() {
        double far = 0;
        for (Sensor s : sensors) {
            far = StrictMath.max(far, StrictMath.hypot(s.xMm(), s.yMm()));
        }
        return far + REACH_SLACK_MM;
    }

    /**
     * The same robot as measured: a calibration's wheels and proximity response in place of the type's.
     *
     * @param source what the measurement was (robot, date, file), shown by {@code robots}
     * @param wheelBaseMm measured wheel base, mm
     * @param mmPerSecondPerUnit measured speed unit, mm/s
     * @param mmPerPulse measured encoder resolution, mm
     * @param response the fitted response
     * @param offset the fitted reading with nothing in range
     * @param noiseAbs the fitted per-reading noise, counts
     * @param noiseRel the fitted relative noise
     * @param measured the robot's own numbers: its name, the day, each sensor's gain, each wheel's calibration
     * @return the calibrated type
     */
    public RobotType calibrated(String source, double wheelBaseMm, double mmPerSecondPerUnit, double mmPerPulse,
            Response response, double offset, double noiseAbs, double noiseRel, Measured measured) {
        Drive d = drive;
        return new RobotType(name, source, body, new Drive(wheelBaseMm, mmPerSecondPerUnit, d.maxSpeed(), mmPerPulse,
                d.motorPeriodNanos(), d.noisePeriodNanos(), d.moveSpeed(), d.acceleration()), sensors,
                new Proximity(response, offset, noiseAbs, noiseRel, proximity.maxReading()), light, turrets, dialect,
                Objects.requireNonNull(measured, "measured"));
    }

    /**
     * What a calibration measured on one robot ({@code khepera-link calibrate}; docs/calibration.md)
     * that a kind of robot does not fix: a run of it draws no per-robot spread (it is this robot), and
     * multiplies each sensor's gain and each wheel's calibration into the settings' own.
     *
     * @param robot the robot's name (its label in the lab)
     * @param date the day it was measured, {@code YYYY-MM-DD}
     * @param proxGains each sensor's proximity gain on the type's response, in sensor order
     * @param leftCalibration the left wheel's actual over commanded speed
     * @param rightCalibration the right wheel's actual over commanded speed
     * @param capReflectance how much a cap reflects, the wall being 1 (NaN: not measured, the settings' figure)
     * @param robotReflectance how much another robot reflects, the wall being 1 (NaN: not measured)
     * @param tables its measured tables: per sensor, per kind of object, its noise, its lamp response
     *     ({@link MeasuredTables#NONE}: none, the kind's response with the gains above)
     */
    public record Measured(String robot, String date, List<Double> proxGains, double leftCalibration,
            double rightCalibration, double capReflectance, double robotReflectance, MeasuredTables tables) {
        public Measured {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(date, "date");
            proxGains = List.copyOf(proxGains);
            tables = tables == null ? MeasuredTables.NONE : tables;
        }

        /** A measured robot without tables of its own: the kind's response, with these gains. */
        public Measured(String robot, String date, List<Double> proxGains, double leftCalibration,
                double rightCalibration, double capReflectance, double robotReflectance) {
            this(robot, date, proxGains, leftCalibration, rightCalibration, capReflectance, robotReflectance,
                    MeasuredTables.NONE);
        }

        /** @param t tables @return this measurement with them */
        public Measured withTables(MeasuredTables t) {
            return new Measured(robot, date, proxGains, leftCalibration, rightCalibration, capReflectance,
                    robotReflectance, t);
        }

        /** @param i a sensor @return its gain */
        public double gain(int i) {
            return proxGains.get(i);
        }
    }

    /** @return whether it carries the gripper turret */
    public boolean hasGripper() {
        return turrets.contains(Turret.GRIPPER);
    }

    /** @return whether it carries the linear vision turret */
    public boolean hasVision() {
        return turrets.contains(Turret.VISION);
    }

    /**
     * The body: a disc (the Khepera and the e-puck are round; the contact solver assumes discs).
     *
     * @param radiusMm the disc's radius, mm
     */
    public record Body(double radiusMm) {
    }

    /**
     * Two wheels on a common axis through the centre, and the robot's motor controller.
     *
     * @param wheelBaseMm distance between the wheels' contact points, mm
     * @param mmPerSecondPerUnit wheel speed of one speed unit, mm/s
     * @param maxSpeed the largest speed magnitude the robot accepts, speed units
     * @param mmPerPulse wheel travel of one encoder pulse (the encoder's resolution), mm
     * @param motorPeriodNanos the motor controller's period: position moves advance this often, ns
     * @param noisePeriodNanos how often each wheel's speed noise is redrawn, ns
     * @param moveSpeed the default top speed of a position move, speed units
     * @param acceleration the default acceleration of a position move, 1/256 speed unit per motor period
     */
    public record Drive(double wheelBaseMm, double mmPerSecondPerUnit, int maxSpeed, double mmPerPulse,
            long motorPeriodNanos,
            long noisePeriodNanos, int moveSpeed, int acceleration) {
    }

    /**
     * One infrared sensor.
     *
     * @param name its name on the robot ({@code LEFT_90}, {@code ps5})
     * @param channel its index in the robot's own protocol replies
     * @param xMm position forward of the centre, mm
     * @param yMm position left of the centre, mm
     * @param headingDeg the direction it looks, degrees counter-clockwise from ahead
     */
    public record Sensor(String name, int channel, double xMm, double yMm, double headingDeg) {
    }

    /**
     * The proximity side of the sensors.
     *
     * @param response reading over distance and angle
     * @param offset reading with nothing in range, counts
     * @param noiseAbs per-reading noise, standard deviation, counts
     * @param noiseRel per-reading noise, standard deviation relative to the signal
     * @param maxReading the largest reading, counts
     */
    public record Proximity(Response response, double offset, double noiseAbs, double noiseRel, int maxReading) {
        /**
         * @return the largest reading the sensors give, counts, noise aside: the response's peak plus the
         *     offset, within {@link #maxReading()} (a Khepera's saturate at its 1023; the bundled e-puck's
         *     reach 2976 of their 4095)
         */
        public int contactReading() {
            return (int) StrictMath.min(maxReading, StrictMath.round(offset + response.peak()));
        }
    }

    /**
     * The ambient-light side of the sensors (lower is brighter).
     *
     * @param dark reading in darkness, counts
     * @param bright reading next to a lamp, counts
     * @param noiseRel per-reading noise of the signal, relative standard deviation
     * @param noiseOfReading per-reading noise relative to the reading itself, standard deviation (the
     *     original WSU simulator's kind: as large in darkness as next to a lamp, relative to the
     *     number); 0 for a real robot
     */
    public record Light(double dark, double bright, double noiseRel, double noiseOfReading) {
        /** A light side without noise of the reading's kind (every real robot's). */
        public Light(double dark, double bright, double noiseRel) {
            this(dark, bright, noiseRel, 0);
        }
    }

    /** A turret a robot may carry. */
    public enum Turret {
        /** The gripper turret (arm and fingers). */
        GRIPPER,
        /** The K213 linear vision turret. */
        VISION
    }
}
