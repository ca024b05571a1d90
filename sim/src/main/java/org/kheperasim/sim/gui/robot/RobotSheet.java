package org.kheperasim.sim.gui.robot;

import java.util.function.Consumer;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.table.AbstractTableModel;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot's numbers as a two-column property sheet: its name, body radius, wheel base, speed
 * unit and speed limit, then each sensor's name, position and heading. A typed value goes through
 * {@link RobotDraft}; one that is not a number or is refused leaves the robot as it was, and the
 * one-line reason (the field, the value, the fix) goes to the refusal consumer.
 */
final class RobotSheet extends AbstractTableModel {
    /** Rows before the sensors'. */
    static final int HEAD = 5;
    /** Rows per sensor. */
    static final int PER_SENSOR = 4;
    private static final String[] HEAD_LABELS = {"name", "body radius, mm", "wheel base, mm", "speed unit, mm/s",
        "max speed, units"};
    private static final String[] SENSOR_LABELS = {"name", "x (forward), mm", "y (left), mm", "heading, degrees"};

    private final RobotDraft draft;
    private final Consumer<String> refusal;

    /** @param draft the robot shown and edited @param refusal told why an edit was refused, or null when it was not */
    RobotSheet(RobotDraft draft, Consumer<String> refusal) {
        this.draft = draft;
        this.refusal = refusal;
        draft.onChange(this::fireTableDataChanged);
    }

    /** @return the sheet's table, one click to edit */
    JTable table() {
        JTable t = new JTable(this);
        t.setName("robotSheet");
        t.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        t.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        t.getColumnModel().getColumn(0).setPreferredWidth(150);
        t.getSelectionModel().addListSelectionListener(e -> {
            int row = t.getSelectedRow();
            if (!e.getValueIsAdjusting() && row >= HEAD) {
                draft.select((row - HEAD) / PER_SENSOR);
            }
        });
        return t;
    }

    /**
     * @param label a row's label, e.g. {@code wheel base, mm} or {@code sensor 3 heading, degrees} @return its row, or
     *     -1
     */
    int row(String label) {
        for (int r = 0; r < getRowCount(); r++) {
            if (getValueAt(r, 0).equals(label)) {
                return r;
            }
        }
        return -1;
    }

    @Override
    public int getRowCount() {
        return HEAD + PER_SENSOR * draft.type().sensorCount();
    }

    @Override
    public int getColumnCount() {
        return 2;
    }

    @Override
    public String getColumnName(int c) {
        return c == 0 ? "Property" : "Value";
    }

    @Override
    public boolean isCellEditable(int r, int c) {
        return c == 1;
    }

    @Override
    public Object getValueAt(int r, int c) {
        RobotType t = draft.type();
        if (r < HEAD) {
            if (c == 0) {
                return HEAD_LABELS[r];
            }
            return switch (r) {
                case 0 -> t.name();
                case 1 -> RobotChecks.num(t.body().radiusMm());
                case 2 -> RobotChecks.num(t.drive().wheelBaseMm());
                case 3 -> RobotChecks.num(t.drive().mmPerSecondPerUnit());
                default -> Integer.toString(t.drive().maxSpeed());
            };
        }
        int i = (r - HEAD) / PER_SENSOR;
        int k = (r - HEAD) % PER_SENSOR;
        if (c == 0) {
            return "sensor " + i + " " + SENSOR_LABELS[k];
        }
        RobotType.Sensor s = t.sensor(i);
        return switch (k) {
            case 0 -> s.name();
            case 1 -> RobotChecks.num(s.xMm());
            case 2 -> RobotChecks.num(s.yMm());
            default -> RobotChecks.num(s.headingDeg());
        };
    }

    @Override
    public void setValueAt(Object value, int r, int c) {
        String text = String.valueOf(value).strip();
        String label = (String) getValueAt(r, 0);
        String why;
        try {
            why = set(r, text);
        } catch (NumberFormatException e) {
            why = label.replaceFirst(",.*", "") + " '" + text + "' is not a number; give " + unitOf(label) + ", e.g. "
                    + getValueAt(r, 1);
        }
        refusal.accept(why);
        fireTableDataChanged();
    }

    private String set(int r, String text) {
        if (r < HEAD) {
            return switch (r) {
                case 0 -> draft.setName(text);
                case 1 -> draft.setBodyRadius(number(text));
                case 2 -> draft.setWheelBase(number(text));
                case 3 -> draft.setSpeedUnit(number(text));
                default -> draft.setMaxSpeed(Integer.parseInt(text));
            };
        }
        int i = (r - HEAD) / PER_SENSOR;
        return switch ((r - HEAD) % PER_SENSOR) {
            case 0 -> draft.renameSensor(i, text);
            case 1 -> draft.moveSensor(i, number(text), draft.type().sensor(i).yMm());
            case 2 -> draft.moveSensor(i, draft.type().sensor(i).xMm(), number(text));
            default -> draft.turnSensor(i, number(text));
        };
    }

    private static double number(String text) {
        double v = Double.parseDouble(text);
        if (!Double.isFinite(v)) {
            throw new NumberFormatException(text);
        }
        return v;
    }

    private static String unitOf(String label) {
        int comma = label.indexOf(", ");
        return comma < 0 ? "a number" : label.substring(comma + 2).equals("units") ? "a whole number of speed units"
                : label.substring(comma + 2);
    }
}
