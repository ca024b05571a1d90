package org.kheperasim.sim.gui.robot;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.JTable;
import javax.swing.SpinnerNumberModel;
import javax.swing.table.AbstractTableModel;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The sensors' proximity response at a chosen angle off the axis: as a curve over distance
 * ({@link ResponsePlot}) and as table rows (distance, reading), with what kind of response it is
 * (one curve weighted per beam angle, or a table over distance and angle).
 */
final class ResponsePanel extends JPanel {
    private final RobotDraft draft;
    private final ResponsePlot plot = new ResponsePlot();
    private final JSpinner angle = new JSpinner(new SpinnerNumberModel(0.0, 0.0, 89.0, 1.0));
    private final JLabel kind = new JLabel();
    private final Rows rows = new Rows();

    ResponsePanel(RobotDraft draft) {
        super(new BorderLayout(4, 4));
        this.draft = draft;
        angle.setName("responseAngle");
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        top.add(new JLabel("Response at"));
        top.add(angle);
        top.add(new JLabel("degrees off the axis"));
        JPanel north = new JPanel(new BorderLayout());
        north.add(top, BorderLayout.NORTH);
        north.add(kind, BorderLayout.SOUTH);
        add(north, BorderLayout.NORTH);
        add(plot, BorderLayout.CENTER);
        JTable table = new JTable(rows);
        table.setName("responseRows");
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new java.awt.Dimension(170, 150));
        add(scroll, BorderLayout.EAST);
        angle.addChangeListener(e -> refresh());
        draft.onChange(this::refresh);
        refresh();
    }

    /** @param deg the angle to show, degrees off the axis */
    void showAngle(double deg) {
        angle.setValue(deg);
    }

    /** @return the rows shown: distance, mm, and reading */
    double[][] rows() {
        return rows.data;
    }

    private void refresh() {
        RobotType t = draft.type();
        Response r = t.proximity().response();
        double a = ((Number) angle.getValue()).doubleValue();
        StringBuilder angles = new StringBuilder();
        for (double x : r.anglesDeg()) {
            angles.append(angles.length() == 0 ? "" : ", ").append(RobotChecks.num(x));
        }
        String form = r instanceof Response.Curve ? "a curve, weighted per beam angle"
                : "a table over distance and angle";
        kind.setText("<html>Sensor " + draft.selected() + " (" + t.sensor(draft.selected()).name() + "): " + form
                + "; beams at " + angles + " degrees; range " + RobotChecks.num(r.rangeMm()) + " mm; offset "
                + RobotChecks.num(t.proximity().offset()) + " and noise come on top</html>");
        double[] d = distances(r);
        double[][] data = new double[d.length][];
        for (int i = 0; i < d.length; i++) {
            data[i] = new double[] {d[i], r.valueAt(d[i], a)};
        }
        rows.data = data;
        rows.fireTableDataChanged();
        plot.show(r, a, t.proximity().maxReading());
    }

    /** @return the response's own distances (a curve's profile, a table's columns) */
    private static double[] distances(Response r) {
        if (r instanceof Response.Table t) {
            return t.distancesMm();
        }
        return r.along(0).distancesMm();
    }

    /** The table rows: distance and reading at the chosen angle. */
    private static final class Rows extends AbstractTableModel {
        private double[][] data = new double[0][];

        @Override
        public int getRowCount() {
            return data.length;
        }

        @Override
        public int getColumnCount() {
            return 2;
        }

        @Override
        public String getColumnName(int c) {
            return c == 0 ? "distance, mm" : "reading";
        }

        @Override
        public Object getValueAt(int r, int c) {
            return c == 0 ? RobotChecks.num(data[r][0]) : RobotChecks.num(StrictMath.rint(data[r][1] * 10) / 10);
        }
    }
}
