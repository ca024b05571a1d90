package org.kheperasim.sim.gui;

import java.awt.Cursor;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * The arena view: hosts {@link ArenaRenderer#draw}, turns mouse events into {@link EditGestures}
 * (left button) and pan (middle or right button drag) and zoom (wheel, about the mouse).
 */
final class ArenaView extends JComponent {
    private final EditorModel model;
    private final EditGestures gestures;
    /** The robot the panels show: a click on a robot of the run selects it. */
    private final RobotSelection selection;
    private boolean clickedRobot;
    private final Supplier<Snapshot> snapshot;
    private final Supplier<List<float[]>> trails;
    private final ViewTransform view = new ViewTransform();
    private ArenaRenderer.Options options = ArenaRenderer.Options.all();
    private boolean fitted;
    private java.util.function.BooleanSupplier editable = () -> true;
    private int lastW;
    private int lastH;
    private double mouseX = Double.NaN;
    private double mouseY = Double.NaN;
    private int panX;
    private int panY;
    private boolean panning;
    private long frames;
    private BufferedImage background;
    private String backgroundKey;

    /** @param e whether mouse gestures edit the arena now (not while a replay is shown: then they pan) */
    void setEditable(java.util.function.BooleanSupplier e) {
        editable = e;
    }

    ArenaView(EditorModel model, EditGestures gestures, Supplier<Snapshot> snapshot, Supplier<List<float[]>> trails,
            RobotSelection selection) {
        this.selection = selection;
        this.model = model;
        this.gestures = gestures;
        this.snapshot = snapshot;
        this.trails = trails;
        setName("arenaView");
        setPreferredSize(new Dimension(640, 640));
        setFocusable(true);
        setOpaque(true);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                int clicked = SwingUtilities.isLeftMouseButton(e) && !e.isShiftDown() && !e.isControlDown()
                        ? RobotSelection.robotAt(snapshot.get(), view.ax(e.getX()), view.ay(e.getY())) : -1;
                if (clicked < 0 && SwingUtilities.isLeftMouseButton(e)) {
                    // No run: a click on a robot's start selects that robot too (and may move it).
                    int start = RobotSelection.startAt(model.shown(), view.ax(e.getX()), view.ay(e.getY()));
                    if (start >= 0) {
                        selection.select(start);
                    }
                }
                if (clicked >= 0) {
                    // A robot of the run: the sensor panel and the plot follow it (no edit starts).
                    selection.select(clicked);
                    clickedRobot = true;
                } else if (SwingUtilities.isLeftMouseButton(e) && !e.isAltDown() && editable.getAsBoolean()) {
                    gestures.press(view.ax(e.getX()), view.ay(e.getY()), e.isShiftDown() || e.isControlDown(),
                            6 / view.scale());
                } else {
                    panning = true;
                    panX = e.getX();
                    panY = e.getY();
                    setCursor(Cursor.getPredefinedCursor(Cursor.MOVE_CURSOR));
                }
                repaint();
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                track(e);
                if (clickedRobot) {
                    return;
                }
                if (panning) {
                    view.pan(e.getX() - panX, e.getY() - panY);
                    panX = e.getX();
                    panY = e.getY();
                } else {
                    gestures.drag(view.ax(e.getX()), view.ay(e.getY()));
                }
                repaint();
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                if (clickedRobot) {
                    clickedRobot = false;
                    return;
                }
                if (panning) {
                    panning = false;
                    setCursor(Cursor.getDefaultCursor());
                } else if (SwingUtilities.isLeftMouseButton(e)) {
                    gestures.release(view.ax(e.getX()), view.ay(e.getY()));
                }
                repaint();
            }

            @Override
            public void mouseMoved(MouseEvent e) {
                track(e);
            }

            @Override
            public void mouseExited(MouseEvent e) {
                mouseX = Double.NaN;
                mouseY = Double.NaN;
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                view.zoomAt(e.getX(), e.getY(), StrictMath.pow(1.15, -e.getPreciseWheelRotation()));
                repaint();
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
    }

    private void track(MouseEvent e) {
        mouseX = view.ax(e.getX());
        mouseY = view.ay(e.getY());
    }

    /** @return the arena position under the mouse, mm, or NaNs */
    double[] mouse() {
        return new double[] {mouseX, mouseY};
    }

    ViewTransform view() {
        return view;
    }

    void setOptions(ArenaRenderer.Options o) {
        options = o;
        repaint();
    }

    ArenaRenderer.Options options() {
        return options;
    }

    void fit() {
        fitted = false;
        repaint();
    }

    void zoom(double factor) {
        view.zoomAt(getWidth() / 2.0, getHeight() / 2.0, factor);
        repaint();
    }

    long frames() {
        return frames;
    }

    @Override
    protected void paintComponent(Graphics g) {
        int w = getWidth();
        int h = getHeight();
        if (!fitted || w != lastW || h != lastH) {
            view.fit(model.shown().width(), model.shown().height(), w, h, 16);
            fitted = true;
            lastW = w;
            lastH = h;
        }
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            List<float[]> t = options.trail() ? trails.get() : new ArrayList<>();
            Arena shown = model.shown();
            String key = System.identityHashCode(shown) + " " + view.sx(0) + " " + view.sy(0) + " " + view.scale() + " "
                    + w + "x" + h + " " + options.grid();
            if (background == null || !key.equals(backgroundKey) || background.getWidth() != w
                    || background.getHeight() != h) {
                background = getGraphicsConfiguration() != null ? getGraphicsConfiguration().createCompatibleImage(w, h)
                        : new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
                Graphics2D bg = background.createGraphics();
                ArenaRenderer.drawStatic(bg, view, w, h, shown, options);
                bg.dispose();
                backgroundKey = key;
            }
            g2.drawImage(background, 0, 0, null);
            Snapshot now = snapshot.get();
            ArenaRenderer.drawDynamic(g2, view, shown, now,
                    new ArenaRenderer.Overlay(model.selection(), gestures.band(), gestures.refusedAt(), t), options);
            RobotLabels.draw(g2, view, now, selection.index());
        } finally {
            g2.dispose();
        }
        frames++;
    }
}
