package org.kheperasim.sim.gui.robot;

import java.util.HashMap;
import java.util.Map;
import java.util.regex.Pattern;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot editor's own checks of an edited robot: each problem is one line naming the field, the
 * value and the fix, so that the property sheet and a drag can refuse it without an exception.
 * The bounds are those of the robot file's reader, plus what makes sense on a drawing: the wheels
 * sit under the body and every sensor is mounted on it.
 */
final class RobotChecks {
    /** The most sensors a robot may have (as the robot file's reader allows). */
    static final int MAX_SENSORS = 32;
    private static final Pattern TYPE_NAME = Pattern.compile("[A-Za-z0-9_-]{1,40}");
    private static final Pattern SENSOR_NAME = Pattern.compile("[A-Za-z0-9_]{1,20}");
    /** What a sensor's mount may stick out of the body, mm (rounding of a dragged position). */
    private static final double MOUNT_SLACK_MM = 1e-6;

    private RobotChecks() {
    }

    /** @param t an edited robot @return what is wrong with it, one line, or null */
    static String problem(RobotType t) {
        if (!TYPE_NAME.matcher(t.name()).matches()) {
            return "name '" + t.name() + "' is not allowed; use 1 to 40 letters, digits, '_' or '-'";
        }
        double r = t.body().radiusMm();
        String p = range("body radius", r, 5, 500, "mm");
        if (p != null) {
            return p;
        }
        RobotType.Drive d = t.drive();
        p = range("wheel base", d.wheelBaseMm(), 1, 1000, "mm");
        if (p == null && d.wheelBaseMm() > 2 * r) {
            p = "wheel base " + num(d.wheelBaseMm()) + " mm is wider than the body (" + num(2 * r)
                    + " mm across); give at most " + num(2 * r) + " mm, or a larger body radius";
        }
        if (p == null) {
            p = range("speed unit", d.mmPerSecondPerUnit(), 1e-4, 1000, "mm/s per unit");
        }
        if (p == null && (d.maxSpeed() < 1 || d.maxSpeed() > 100_000)) {
            p = "max speed " + d.maxSpeed() + " is out of range; give a whole number of speed units from 1 to 100000";
        }
        if (p == null && d.maxSpeed() < d.moveSpeed()) {
            p = "max speed " + d.maxSpeed() + " is below the position moves' speed " + d.moveSpeed() + "; give "
                    + d.moveSpeed() + " at least";
        }
        return p != null ? p : sensors(t);
    }

    private static String sensors(RobotType t) {
        if (t.sensorCount() > MAX_SENSORS) {
            return t.sensorCount() + " sensors is too many; a robot has at most " + MAX_SENSORS;
        }
        Map<String, Integer> names = new HashMap<>();
        double r = t.body().radiusMm();
        for (int i = 0; i < t.sensorCount(); i++) {
            RobotType.Sensor s = t.sensor(i);
            if (!SENSOR_NAME.matcher(s.name()).matches()) {
                return "sensor " + i + " name '" + s.name() + "' is not allowed; use 1 to 20 letters, digits or '_'";
            }
            Integer before = names.putIfAbsent(s.name(), i);
            if (before != null) {
                return "sensor name '" + s.name() + "' is used twice (sensors " + before + " and " + i
                        + "); give each sensor its own name";
            }
            if (!Double.isFinite(s.xMm()) || !Double.isFinite(s.yMm()) || !Double.isFinite(s.headingDeg())) {
                return "sensor " + i + " (" + s.name()
                        + ") has a position or heading that is not a number; give mm and degrees";
            }
            double at = StrictMath.hypot(s.xMm(), s.yMm());
            if (at > r + MOUNT_SLACK_MM) {
                return "sensor " + i + " (" + s.name() + ") at (" + num(s.xMm()) + ", " + num(s.yMm()) + ") mm is "
                        + num(StrictMath.rint(at * 100) / 100) + " mm from the centre, off the body (radius " + num(r)
                        + " mm); mount it within the body";
            }
        }
        return null;
    }

    private static String range(String field, double v, double lo, double hi, String unit) {
        if (!(v >= lo && v <= hi)) {
            return field + " " + num(v) + " " + unit + " is out of range; give " + num(lo) + " to "
                    + num(hi) + " " + unit;
        }
        return null;
    }

    /** @param v a number @return it in its shortest decimal form ({@code 27.5}, {@code 53}) */
    static String num(double v) {
        if (!Double.isFinite(v)) {
            return String.valueOf(v);
        }
        if (v == StrictMath.rint(v) && StrictMath.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }
}
