package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.Insets;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JPanel;
import javax.swing.JToggleButton;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.replay.RobotSeries;

/**
 * The plot: any proximity or light sensor, the wheel speeds or the encoders of the selected robot,
 * over the last 10 s, 60 s, 10 min or the whole run, with axes in seconds and the quantity's units.
 * The shown data exports as CSV and the view as PNG.
 */
final class PlotPanel extends JPanel {
    /** The quantities offered: label, first channel, channels, axis title, fixed top or NaN. */
    private enum Quantity {
        PROXIMITY("Proximity", RobotSeries.PROXIMITY, 8, "proximity, 0..1023 (higher = nearer)", 1023),
        LIGHT("Light", RobotSeries.LIGHT, 8, "light, 0..1023 (lower = brighter)", 1023),
        SPEED("Wheel speed", RobotSeries.SPEED, 2, "speed, units (1 = 8 mm/s)", Double.NaN),
        ENCODER("Encoders", RobotSeries.ENCODER, 2, "encoder, pulses (1 = 0.08 mm)", Double.NaN);

        final String label;
        final int first;
        final int count;
        final String unit;
        final double max;

        Quantity(String label, int first, int count, String unit, double max) {
            this.label = label;
            this.first = first;
            this.count = count;
            this.unit = unit;
            this.max = max;
        }

        @Override
        public String toString() {
            return label;
        }
    }

    /** Spans offered, s; the last is the whole run. */
    static final double[] SPANS = {10, 60, 600, Double.POSITIVE_INFINITY};

    private org.kheperasim.sim.engine.robot.RobotType type = org.kheperasim.sim.engine.robot.RobotTypes.KHEPERA1;
    private final PlotCanvas canvas = new PlotCanvas();
    private final JComboBox<Quantity> quantity = new JComboBox<>(Quantity.values());
    private final JComboBox<String> span =
            new JComboBox<>(new String[] {"last 10 s", "last 60 s", "last 10 min", "whole run"});
    private final JToggleButton[] chosen = new JToggleButton[8];
    private RobotSeries series;
    private double now;
    private double cursor = Double.NaN;

    PlotPanel() {
        super(new BorderLayout());
        setName("plotPanel");
        quantity.setName("plot.quantity");
        span.setName("plot.span");
        quantity.setFocusable(false);
        span.setFocusable(false);
        quantity.addActionListener(e -> relabel());
        span.addActionListener(e -> refresh());
        JPanel top = new JPanel(new BorderLayout());
        // Wraps onto a second row when the plot is narrow (side by side with the sensor panel on a short window).
        JPanel row = new JPanel(new WrapLayout());
        row.add(quantity);
        row.add(span);
        JButton csv = new JButton("CSV…");
        csv.setName("plot.csv");
        csv.setToolTipText("save the plotted samples as CSV");
        csv.addActionListener(e -> export(true));
        JButton png = new JButton("PNG…");
        png.setName("plot.png");
        png.setToolTipText("save the plot as a PNG picture");
        png.addActionListener(e -> export(false));
        for (JButton b : new JButton[] {csv, png}) {
            b.setMargin(new Insets(0, 2, 0, 2));
            b.setFocusable(false);
            row.add(b);
        }
        top.add(row, BorderLayout.NORTH);
        JPanel buttons = new JPanel(new GridLayout(1, 8, 1, 1));
        for (int i = 0; i < 8; i++) {
            JToggleButton b = new JToggleButton(Integer.toString(i), i == 2 || i == 3);
            b.setMargin(new Insets(0, 1, 0, 1));
            b.setFont(b.getFont().deriveFont(10f));
            b.setForeground(PlotCanvas.COLOURS[i]);
            b.setFocusable(false);
            b.addActionListener(e -> refresh());
            chosen[i] = b;
            buttons.add(b);
        }
        top.add(buttons, BorderLayout.SOUTH);
        canvas.setPreferredSize(new Dimension(320, 170));
        addComponentListener(new java.awt.event.ComponentAdapter() {
            @Override
            public void componentResized(java.awt.event.ComponentEvent e) {
                row.revalidate();
            }
        });
        add(top, BorderLayout.NORTH);
        add(canvas, BorderLayout.CENTER);
        relabel();
    }

    private void relabel() {
        Quantity q = (Quantity) quantity.getSelectedItem();
        for (int i = 0; i < 8; i++) {
            chosen[i].setVisible(i < q.count);
            chosen[i].setText(q.count == 2 ? (i == 0 ? "left" : "right") : Integer.toString(i));
            if (q.count == 2) {
                chosen[i].setSelected(true);
            }
        }
        refresh();
    }

    /** @param index which span: 0 last 10 s, 1 last 60 s, 2 last 10 min, 3 whole run */
    void chooseSpan(int index) {
        span.setSelectedIndex(index);
    }

    /**
     * @param s the selected robot's samples, or null
     * @param nowSeconds the time shown (the span ends here)
     * @param cursorSeconds a time to mark (the replay's), or NaN
     */
    void show(RobotSeries s, org.kheperasim.sim.engine.robot.RobotType robotType, double nowSeconds,
            double cursorSeconds) {
        series = s;
        type = robotType == null ? org.kheperasim.sim.engine.robot.RobotTypes.KHEPERA1 : robotType;
        now = nowSeconds;
        cursor = cursorSeconds;
        refresh();
    }

    private void refresh() {
        RobotSeries s = series;
        if (s == null || s.size() == 0) {
            canvas.show(null);
            return;
        }
        double[] range = range(s);
        int[] channels = channels();
        canvas.show(new PlotCanvas.Plot(
                s.extract(range[0], range[1], channels, StrictMath.max(200, canvas.getWidth() * 2)),
                labels(channels), colours(), range[0], range[1], top((Quantity) quantity.getSelectedItem()),
                unit((Quantity) quantity.getSelectedItem()), cursor));
    }

    /** @return the quantity's fixed top on the selected robot's scale (proximity: its max_reading), or NaN */
    private double top(Quantity q) {
        return q == Quantity.PROXIMITY ? type.proximity().maxReading() : q.max;
    }

    /** @return the axis title in the selected robot's numbers (its proximity scale, speed unit, pulse) */
    private String unit(Quantity q) {
        return switch (q) {
            case PROXIMITY -> "proximity, 0.." + type.proximity().maxReading() + " (higher = nearer)";
            case SPEED -> "speed, units (1 = " + plain(type.drive().mmPerSecondPerUnit()) + " mm/s)";
            case ENCODER -> "encoder, pulses (1 = " + plain(type.drive().mmPerPulse()) + " mm)";
            default -> q.unit;
        };
    }

    private static String plain(double v) {
        return new java.math.BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
    }

    private double[] range(RobotSeries s) {
        double len = SPANS[span.getSelectedIndex()];
        double first = s.time(0);
        if (Double.isInfinite(len)) {
            return new double[] {first, StrictMath.max(Double.isNaN(cursor) ? now : s.lastTime(), first)};
        }
        return new double[] {StrictMath.max(first, now - len), now};
    }

    private int[] channels() {
        Quantity q = (Quantity) quantity.getSelectedItem();
        List<Integer> out = new ArrayList<>();
        for (int i = 0; i < q.count; i++) {
            if (chosen[i].isSelected()) {
                out.add(q.first + i);
            }
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    private int[] colours() {
        Quantity q = (Quantity) quantity.getSelectedItem();
        List<Integer> out = new ArrayList<>();
        for (int i = 0; i < q.count; i++) {
            if (chosen[i].isSelected()) {
                out.add(i);
            }
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    private static String[] labels(int[] channels) {
        String[] out = new String[channels.length];
        for (int i = 0; i < channels.length; i++) {
            out[i] = RobotSeries.channelName(channels[i]);
        }
        return out;
    }

    /** @return the samples shown, as CSV: {@code t_s} and one column per plotted channel, at full resolution */
    String csv() {
        RobotSeries s = series;
        int[] channels = channels();
        StringBuilder b = new StringBuilder("t_s");
        for (String l : labels(channels)) {
            b.append(',').append(l);
        }
        b.append('\n');
        if (s != null && s.size() > 0) {
            double[] range = range(s);
            double[][] d = s.extract(range[0], range[1], channels, 0);
            for (int k = 0; k < d[0].length; k++) {
                b.append(String.format(Locale.ROOT, "%.3f", d[0][k]));
                for (int c = 1; c < d.length; c++) {
                    b.append(',').append((long) d[c][k]);
                }
                b.append('\n');
            }
        }
        return b.toString();
    }

    /** @return the plot as a picture at its size on screen */
    BufferedImage image() {
        BufferedImage img = new BufferedImage(StrictMath.max(1, canvas.getWidth()),
                StrictMath.max(1, canvas.getHeight()),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            canvas.paintPlot(g, img.getWidth(), img.getHeight());
        } finally {
            g.dispose();
        }
        return img;
    }

    /** @param file where to write (atomically, as every save) @param asCsv CSV of the data, else PNG of the view */
    void exportTo(Path file, boolean asCsv) {
        try {
            if (asCsv) {
                AtomicFiles.write(file, csv());
            } else {
                AtomicFiles.writePng(file, image());
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file + ": " + e.getMessage(), e);
        }
    }

    private void export(boolean asCsv) {
        JFileChooser c = new JFileChooser();
        c.setSelectedFile(new java.io.File(asCsv ? "plot.csv" : "plot.png"));
        if (c.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            exportTo(c.getSelectedFile().toPath(), asCsv);
        }
    }
}
