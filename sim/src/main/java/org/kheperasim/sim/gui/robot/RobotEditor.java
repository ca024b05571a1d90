package org.kheperasim.sim.gui.robot;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Toolkit;
import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.function.BiFunction;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JToolBar;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot editor's window: the robot drawn to scale ({@link RobotCanvas}), its numbers
 * ({@link RobotSheet}), its sensors' response ({@link ResponsePanel}), and the commands Open,
 * Start from (a bundled robot), Save, Save as, Add sensor, Remove sensor and Try in arena. A
 * refused edit is said on the message line in red, one line, and beeps.
 */
public final class RobotEditor {
    /** Robot files' extension. */
    static final String EXTENSION = "yaml";
    /** How a trial that did not happen begins its line. */
    static final String NOT_TRIED = "Not tried: ";

    private final JFrame frame = new JFrame();
    private final RobotFileStore store;
    private final RobotDraft draft;
    private final BiFunction<RobotType, Path, String> trial;
    private final JLabel message = new JLabel(" ");
    private final RobotCanvas canvas;
    private final RobotSheet sheet;
    private final JTable sheetTable;
    private final ResponsePanel response;

    /**
     * @param store the robot files
     * @param start the robot to start from
     * @param file its file, or null (a bundled robot or a new one)
     * @param bundled the robots offered under Start from
     * @param trial puts a robot (and its file when the file holds it, else null) into the main window's arena and
     *     restarts its run; returns what it did, one line
     */
    public RobotEditor(RobotFileStore store, RobotType start, Path file, List<RobotType> bundled,
            BiFunction<RobotType, Path, String> trial) {
        this.store = store;
        this.trial = trial;
        draft = new RobotDraft(store, start, file);
        canvas = new RobotCanvas(draft, this::said);
        sheet = new RobotSheet(draft, this::said);
        sheetTable = sheet.table();
        response = new ResponsePanel(draft);
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        bar.add(button("open", "Open…", this::open));
        JComboBox<String> from = new JComboBox<>();
        from.setName("startFrom");
        from.addItem("Start from…");
        for (RobotType t : bundled) {
            from.addItem(t.name());
        }
        from.addActionListener(e -> {
            int i = from.getSelectedIndex();
            if (i > 0) {
                from.setSelectedIndex(0);
                if (mayDrop("starting from " + bundled.get(i - 1).name())) {
                    draft.load(bundled.get(i - 1), null);
                    said(null);
                }
            }
        });
        bar.add(from);
        bar.addSeparator();
        bar.add(button("save", "Save", () -> save(false)));
        bar.add(button("saveAs", "Save as…", () -> save(true)));
        bar.addSeparator();
        bar.add(button("addSensor", "Add sensor", () -> said(draft.addSensor())));
        bar.add(button("removeSensor", "Remove sensor", () -> said(draft.removeSensor(draft.selected()))));
        bar.addSeparator();
        bar.add(button("tryInArena", "Try in arena", this::tryInArena));
        JSplitPane right = new JSplitPane(JSplitPane.VERTICAL_SPLIT, new JScrollPane(sheetTable), response);
        right.setResizeWeight(0.55);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, canvas, right);
        split.setResizeWeight(0.55);
        message.setName("robotMessage");
        JPanel content = new JPanel(new BorderLayout());
        content.add(bar, BorderLayout.NORTH);
        content.add(split, BorderLayout.CENTER);
        content.add(message, BorderLayout.SOUTH);
        frame.setContentPane(content);
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        draft.onChange(this::retitle);
        retitle();
        frame.setSize(1100, 720);
    }

    /** Shows the window. */
    public void show() {
        frame.setVisible(true);
    }

    /** @param why a refusal, shown in red with a beep; null clears the line */
    private void said(String why) {
        if (why == null) {
            message.setForeground(Color.DARK_GRAY);
            message.setText(" ");
            return;
        }
        message.setForeground(new Color(180, 0, 0));
        message.setText("Refused: " + why);
        Toolkit.getDefaultToolkit().beep();
    }

    private void note(String text) {
        message.setForeground(new Color(0, 90, 0));
        message.setText(text);
    }

    private void retitle() {
        Path f = draft.file();
        frame.setTitle("Robot editor - " + draft.type().name() + (draft.dirty() ? " *" : "")
                + (f != null ? " (" + f + ")" : " (not saved)"));
    }

    private JButton button(String name, String label, Runnable body) {
        JButton b = new JButton(label);
        b.setName(name);
        b.setFocusable(false);
        b.addActionListener(e -> body.run());
        return b;
    }

    private JFileChooser chooser() {
        Path f = draft.file();
        JFileChooser c = new JFileChooser(f != null && f.toAbsolutePath().getParent() != null
                ? f.toAbsolutePath().getParent().toFile() : new File("."));
        c.setFileFilter(new FileNameExtensionFilter("Robot files (." + EXTENSION + ")", EXTENSION));
        return c;
    }

    private void open() {
        JFileChooser c = chooser();
        if (c.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION && mayDrop("opening another robot")) {
            open(c.getSelectedFile().toPath());
        }
    }

    /** @param file a robot file to edit @return whether it was read (a bad one is said on the message line) */
    public boolean open(Path file) {
        try {
            draft.load(store.load(file), file);
            note("Opened " + file);
            return true;
        } catch (RuntimeException e) {
            said(e.getMessage());
            return false;
        }
    }

    /** @param as ask for a file even when the robot has one @return whether it was written */
    private boolean save(boolean as) {
        Path target = draft.file();
        if (as || target == null) {
            JFileChooser c = chooser();
            c.setSelectedFile(new File(draft.type().name() + "." + EXTENSION));
            if (c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
                return false;
            }
            target = c.getSelectedFile().toPath();
            if (!target.getFileName().toString().endsWith("." + EXTENSION)) {
                target = target.resolveSibling(target.getFileName() + "." + EXTENSION);
            }
        }
        return saveTo(target);
    }

    /** @param target where to write the robot @return whether it was written */
    public boolean saveTo(Path target) {
        try {
            store.save(draft.type(), target);
        } catch (RuntimeException e) {
            said("cannot save " + target + ": " + e.getMessage());
            return false;
        }
        draft.saved(target);
        note("Saved " + target);
        return true;
    }

    private void tryInArena() {
        String done = trial.apply(draft.type(), draft.dirty() ? null : draft.file());
        if (done.startsWith(NOT_TRIED)) {
            said(done.substring(NOT_TRIED.length()));
        } else {
            note(done);
        }
    }

    private boolean mayDrop(String doing) {
        if (!draft.dirty()) {
            return true;
        }
        return JOptionPane.showConfirmDialog(frame,
                "The robot " + draft.type().name() + " has unsaved changes. Drop them"
                + " before " + doing + "?", "Unsaved changes", JOptionPane.OK_CANCEL_OPTION) == JOptionPane.OK_OPTION;
    }

    // ---- for tests and drivers ----

    /** @return the window */
    public JFrame frame() {
        return frame;
    }

    /** @return the robot as edited */
    public RobotType robot() {
        return draft.type();
    }

    /** @return the message line's text */
    public String messageText() {
        return message.getText();
    }

    /** @return the drawing */
    public javax.swing.JComponent canvas() {
        return canvas;
    }

    /** @param i a sensor @return the handle at its beam's tip, in the canvas' pixels */
    public java.awt.geom.Point2D tipOnCanvas(int i) {
        return canvas.tip(i);
    }

    /** @param i a sensor @return its mount, in the canvas' pixels */
    public java.awt.geom.Point2D mountOnCanvas(int i) {
        return canvas.mount(i);
    }

    /** @param x mm forward @param y mm left @return where that point is drawn, in the canvas' pixels */
    public java.awt.geom.Point2D onCanvas(double x, double y) {
        return canvas.toScreen(x, y);
    }

    /** @return the property sheet */
    public JTable sheet() {
        return sheetTable;
    }

    /** @param label a property's label, e.g. {@code wheel base, mm} @return its row in the sheet, or -1 */
    public int sheetRow(String label) {
        return sheet.row(label);
    }

    /** @param deg the response angle to show @return the rows shown (distance, reading) */
    public double[][] responseAt(double deg) {
        response.showAngle(deg);
        return response.rows();
    }

    /** Presses Try in arena. */
    public void tryIt() {
        tryInArena();
    }

    /** @return whether the robot has changes not saved */
    public boolean dirty() {
        return draft.dirty();
    }
}
