package org.kheperasim.sim.engine.robot;

import java.util.Locale;

/**
 * Writes a {@link RobotType} as a robot file ({@code docs/robot-files.md}), in the one canonical
 * layout: keys in a fixed order, numbers in their shortest decimal form, no comments. What it
 * writes {@link RobotFileReader} reads back to the same type, and writing that again gives the
 * same bytes.
 */
public final class RobotFileWriter {

    private RobotFileWriter() {
    }

    /** @param t a robot type @return its robot file */
    public static String write(RobotType t) {
        StringBuilder sb = new StringBuilder();
        sb.append("# robot file, format in docs/robot-files.md\n");
        sb.append("name: ").append(t.name()).append('\n');
        if (!t.source().isEmpty()) {
            sb.append("source: ").append(t.source()).append('\n');
        }
        sb.append("dialect: ").append(t.dialect()).append('\n');
        sb.append("turrets: [");
        String sep = "";
        for (RobotType.Turret turret : RobotType.Turret.values()) {
            if (t.turrets().contains(turret)) {
                sb.append(sep).append(turret.name().toLowerCase(Locale.ROOT));
                sep = ", ";
            }
        }
        sb.append("]\n");
        sb.append("footprint:\n  type: circle\n");
        key(sb, "radius", t.body().radiusMm());
        RobotType.Drive d = t.drive();
        sb.append("drive:\n");
        key(sb, "wheel_base", d.wheelBaseMm());
        key(sb, "speed_unit", d.mmPerSecondPerUnit());
        key(sb, "max_speed", d.maxSpeed());
        key(sb, "encoder_resolution", d.mmPerPulse());
        key(sb, "motor_period", d.motorPeriodNanos() / 1e6);
        key(sb, "noise_period", d.noisePeriodNanos() / 1e6);
        key(sb, "move_speed", d.moveSpeed());
        key(sb, "acceleration", d.acceleration());
        sb.append("sensors:\n");
        for (RobotType.Sensor s : t.sensors()) {
            sb.append("  - name: ").append(s.name()).append('\n');
            sb.append("    channel: ").append(s.channel()).append('\n');
            sb.append("    origin: ").append(list(new double[] {s.xMm(), s.yMm(), s.headingDeg()})).append('\n');
        }
        RobotType.Proximity p = t.proximity();
        sb.append("proximity:\n");
        if (p.response() instanceof Response.Curve c) {
            sb.append("  response: curve\n");
            sb.append("  angles: ").append(list(c.anglesDeg())).append('\n');
            sb.append("  weights: ").append(list(c.weights())).append('\n');
            sb.append("  distances: ").append(list(c.distance().distancesMm())).append('\n');
            sb.append("  values: ").append(list(c.distance().values())).append('\n');
        } else if (p.response() instanceof Response.Table tb) {
            sb.append("  response: table\n");
            sb.append("  angles: ").append(list(tb.anglesDeg())).append('\n');
            sb.append("  distances: ").append(list(tb.distancesMm())).append('\n');
            sb.append("  values:\n");
            for (double[] row : tb.values()) {
                sb.append("    - ").append(list(row)).append('\n');
            }
        }
        key(sb, "offset", p.offset());
        key(sb, "noise_std_dev", p.noiseAbs());
        key(sb, "noise_relative", p.noiseRel());
        key(sb, "max_reading", p.maxReading());
        sb.append("light:\n");
        key(sb, "dark", t.light().dark());
        key(sb, "bright", t.light().bright());
        key(sb, "noise_relative", t.light().noiseRel());
        if (t.light().noiseOfReading() > 0) {
            key(sb, "noise_of_reading", t.light().noiseOfReading());
        }
        RobotType.Measured m = t.measured();
        if (m != null) {
            sb.append("measured:\n");
            sb.append("  robot: ").append(m.robot()).append('\n');
            sb.append("  date: ").append(m.date()).append('\n');
            double[] gains = new double[m.proxGains().size()];
            for (int i = 0; i < gains.length; i++) {
                gains[i] = m.gain(i);
            }
            sb.append("  gains: ").append(list(gains)).append('\n');
            sb.append("  wheel_calibration: ").append(list(new double[] {m.leftCalibration(), m.rightCalibration()}))
                    .append('\n');
            if (!Double.isNaN(m.capReflectance())) {
                key(sb, "cap_reflectance", m.capReflectance());
            }
            if (!Double.isNaN(m.robotReflectance())) {
                key(sb, "robot_reflectance", m.robotReflectance());
            }
            tables(sb, m.tables());
        }
        return sb.toString();
    }

    /** A measured robot's tables, written out (a file that pointed at sample files is saved with their fits). */
    private static void tables(StringBuilder sb, MeasuredTables t) {
        if (!t.noiseScale().isEmpty()) {
            sb.append("  noise_scale: ").append(list(t.noiseScale().stream().mapToDouble(Double::doubleValue)
                    .toArray())).append('\n');
        }
        Response.Table grid = t.grid();
        if (grid != null) {
            sb.append("  table_angles: ").append(list(grid.anglesDeg())).append('\n');
            sb.append("  table_distances: ").append(list(grid.distancesMm())).append('\n');
            if (!t.sensors().isEmpty()) {
                sb.append("  sensor_tables:\n");
                for (Response r : t.sensors()) {
                    rows(sb, r);
                }
            }
            if (!t.cap().isEmpty()) {
                sb.append("  cap_table:\n");
                t.cap().forEach(r -> rows(sb, r));
            }
            if (!t.robot().isEmpty()) {
                sb.append("  robot_table:\n");
                t.robot().forEach(r -> rows(sb, r));
            }
        }
        if (t.lamp() != null) {
            sb.append("  lamp_distances: ").append(list(t.lamp().distancesMm())).append('\n');
            sb.append("  lamp_activations: ").append(list(t.lamp().activations())).append('\n');
        }
    }

    private static void rows(StringBuilder sb, Response r) {
        for (double[] row : ((Response.Table) r).values()) {
            sb.append("    - ").append(list(row)).append('\n');
        }
    }

    private static void key(StringBuilder sb, String key, double v) {
        sb.append("  ").append(key).append(": ").append(RobotFileReader.fmt(v)).append('\n');
    }

    private static String list(double[] v) {
        StringBuilder sb = new StringBuilder("[");
        for (int i = 0; i < v.length; i++) {
            sb.append(i == 0 ? "" : ", ").append(RobotFileReader.fmt(v[i]));
        }
        return sb.append(']').toString();
    }
}
