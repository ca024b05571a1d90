package org.kheperasim.sim.gui.robot;

import java.awt.GridLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.JTextField;
import javax.swing.SpinnerNumberModel;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * A robot from scratch: a round body, two wheels and a number of sensors spread around the body's
 * edge, three quarters of them over the front half (from the left side, 90 degrees, to the right,
 * in the Khepera's index order) and the rest looking back. What a new robot does not say (its
 * sensors' response, the motor controller's periods, the light levels) it takes from the robot it
 * starts from; it carries no turret.
 */
final class NewRobot {
    /** Where a new robot's sensors sit, as a fraction of the body radius from the centre. */
    private static final double MOUNT_FRACTION = 0.9;

    private NewRobot() {
    }

    /**
     * @param name the robot's name
     * @param radiusMm its body radius, mm
     * @param wheelBaseMm its wheel base, mm
     * @param speedUnit mm/s of one speed unit
     * @param sensors how many sensors
     * @param like the robot whose response, drive periods and light it takes
     * @return the new robot (unchecked: the draft checks it)
     */
    static RobotType design(String name, double radiusMm, double wheelBaseMm, double speedUnit, int sensors,
            RobotType like) {
        int back = sensors / 4;
        int front = sensors - back;
        List<RobotType.Sensor> list = new ArrayList<>();
        double r = radiusMm * MOUNT_FRACTION;
        for (int i = 0; i < front; i++) {
            double h = front == 1 ? 0 : 90 - 180.0 * i / (front - 1);
            list.add(sensor("S" + i, i, r, h, h));
        }
        for (int j = 0; j < back; j++) {
            // Spread across the back, right to left as the Khepera's back pair; each looks straight back.
            double at = back == 1 ? 180 : -150 - 60.0 * j / (back - 1);
            list.add(sensor("S" + (front + j), front + j, r, at, 180));
        }
        RobotType.Drive d = like.drive();
        RobotType.Drive drive = new RobotType.Drive(wheelBaseMm, speedUnit, d.maxSpeed(), d.mmPerPulse(),
                d.motorPeriodNanos(), d.noisePeriodNanos(), d.moveSpeed(), d.acceleration());
        return new RobotType(name, "designed in the robot editor", new RobotType.Body(radiusMm), drive, list,
                RobotDraft.named(like.proximity(), name), like.light(), Set.of(), like.dialect());
    }

    private static RobotType.Sensor sensor(String name, int channel, double r, double atDeg, double headingDeg) {
        double a = StrictMath.toRadians(atDeg);
        double x = StrictMath.rint(r * StrictMath.cos(a) * 2) / 2;
        double y = StrictMath.rint(r * StrictMath.sin(a) * 2) / 2;
        return new RobotType.Sensor(name, channel, x == 0 ? 0 : x, y == 0 ? 0 : y, RobotDraft.normalised(headingDeg));
    }

    /**
     * Asks for the new robot's name, size, wheel base, speed unit and sensor count.
     *
     * @param owner the dialog's owner
     * @param like the robot whose other numbers it takes
     * @return the robot, or null when cancelled or refused (the reason shown)
     */
    static RobotType ask(JFrame owner, RobotType like) {
        JTextField name = new JTextField("myrobot", 12);
        JSpinner radius = new JSpinner(new SpinnerNumberModel(35.0, 5.0, 500.0, 0.5));
        JSpinner base = new JSpinner(new SpinnerNumberModel(60.0, 1.0, 1000.0, 0.5));
        JSpinner unit = new JSpinner(new SpinnerNumberModel(like.drive().mmPerSecondPerUnit(), 1e-4, 1000.0, 0.5));
        JSpinner count = new JSpinner(new SpinnerNumberModel(3, 1, RobotChecks.MAX_SENSORS, 1));
        JPanel p = new JPanel(new GridLayout(5, 2, 4, 4));
        p.add(new JLabel("Name"));
        p.add(name);
        p.add(new JLabel("Body radius, mm"));
        p.add(radius);
        p.add(new JLabel("Wheel base, mm"));
        p.add(base);
        p.add(new JLabel("Speed unit, mm/s"));
        p.add(unit);
        p.add(new JLabel("Sensors"));
        p.add(count);
        if (JOptionPane.showConfirmDialog(owner, p, "New robot",
                JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION) {
            return null;
        }
        RobotType t = design(name.getText().strip(), ((Number) radius.getValue()).doubleValue(),
                ((Number) base.getValue()).doubleValue(), ((Number) unit.getValue()).doubleValue(),
                ((Number) count.getValue()).intValue(), like);
        String why = RobotChecks.problem(t);
        if (why != null) {
            JOptionPane.showMessageDialog(owner, why, "Cannot make the robot", JOptionPane.ERROR_MESSAGE);
            return null;
        }
        return t;
    }
}
