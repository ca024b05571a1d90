package org.kheperasim.sim.gui.robot;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.IntSupplier;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.RobotKind;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The main window's Robot menu: Edit robot (the selected robot's type), Open robot file, New
 * robot, each in a {@link RobotEditor}; and Try in arena, which gives the robot selected in the
 * main window the edited type (an arena edit, undoable there) and starts its run afresh.
 */
public final class RobotEditing {
    private final JFrame owner;
    private final EditorModel model;
    private final IntSupplier selected;
    private final Runnable discardRun;
    private final Runnable startRun;
    private final RobotFileStore store;
    private final List<RobotType> bundled;
    private RobotEditor last;

    /**
     * @param owner the main window
     * @param model the main window's arena
     * @param selected the robot selected there
     * @param discardRun ends the main window's run, if any
     * @param startRun starts a new run of the arena as it is
     * @param store the robot files
     * @param bundled the bundled robots, the default first
     */
    public RobotEditing(JFrame owner, EditorModel model, IntSupplier selected, Runnable discardRun, Runnable startRun,
            RobotFileStore store, List<RobotType> bundled) {
        this.owner = owner;
        this.model = model;
        this.selected = selected;
        this.discardRun = discardRun;
        this.startRun = startRun;
        this.store = store;
        this.bundled = List.copyOf(bundled);
    }

    /** Robot > Edit robot: the editor on the selected robot's type. @return the editor */
    public RobotEditor editSelected() {
        RobotKind k = model.arena().robotKinds().get(index());
        Path f = RobotTypes.BUNDLED.contains(k.spec()) ? null : Path.of(k.spec());
        // Saved back to its file only when the line named the file in full (a relative one is the arena file's).
        boolean own = f != null && f.isAbsolute() && java.nio.file.Files.isRegularFile(f) && holds(f, k.type());
        return show(k.type(), own ? f : null);
    }

    private boolean holds(Path f, RobotType t) {
        try {
            return store.load(f).equals(t);
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** Robot > Open robot file: asks for a file, then edits it. */
    public void openFile() {
        JFileChooser c = new JFileChooser(new File("."));
        // A calibration (khepera-link calibrate) opens as the robot it measured; saving it writes a robot file.
        c.setFileFilter(new FileNameExtensionFilter("Robot files and calibrations (." + RobotEditor.EXTENSION
                + ", .calibration)", RobotEditor.EXTENSION, "calibration"));
        if (c.showOpenDialog(owner) == JFileChooser.APPROVE_OPTION) {
            openFile(c.getSelectedFile().toPath());
        }
    }

    /** @param file a robot file @return its editor, or null when it cannot be read (said in a dialog) */
    public RobotEditor openFile(Path file) {
        RobotType t;
        try {
            t = store.load(file);
        } catch (RuntimeException e) {
            JOptionPane.showMessageDialog(owner, e.getMessage(), "Cannot open the robot", JOptionPane.ERROR_MESSAGE);
            return null;
        }
        return show(t, file);
    }

    /** Robot > New robot: asks for the essentials, then edits the new robot. */
    public void newRobot() {
        RobotType t = NewRobot.ask(owner, bundled.get(0));
        if (t != null) {
            show(t, null);
        }
    }

    /**
     * A new robot without the dialog (drivers).
     *
     * @return its editor
     */
    public RobotEditor newRobot(String name, double radiusMm, double wheelBaseMm, double speedUnit, int sensors) {
        return show(NewRobot.design(name, radiusMm, wheelBaseMm, speedUnit, sensors, bundled.get(0)), null);
    }

    /** @return the last editor opened, or null */
    public RobotEditor last() {
        return last;
    }

    private RobotEditor show(RobotType t, Path file) {
        RobotEditor e = new RobotEditor(store, t, file, bundled, this::tryInArena);
        e.frame().setLocationRelativeTo(owner);
        e.show();
        last = e;
        return e;
    }

    private int index() {
        int i = selected.getAsInt();
        return i >= 0 && i < model.arena().robots().size() ? i : 0;
    }

    /**
     * @param t the robot to try
     * @param file its robot file when the file holds exactly it, else null
     * @return what was done, one line: the robot given the type and the run restarted, or why not
     */
    String tryInArena(RobotType t, Path file) {
        Arena a = model.arena();
        int i = index();
        RobotKind kind;
        String named;
        try {
            kind = kind(t, file);
            named = kind.spec().equals(t.name()) ? "" : " (the arena names it by " + kind.spec() + ")";
        } catch (RuntimeException e) {
            return RobotEditor.NOT_TRIED + e.getMessage();
        }
        List<RobotKind> kinds = new ArrayList<>(a.robotKinds());
        kinds.set(i, kind);
        Arena next = new Arena(a.name(), a.width(), a.height(), a.robots(), a.walls(), a.lights(),
                a.caps(), a.regions(),
                a.assignment(), kinds);
        // A run's robots keep their types: the run ends, the arena takes the type, and a new run starts with it.
        discardRun.run();
        if (!model.apply(next)) {
            return RobotEditor.NOT_TRIED + model.lastRefusal();
        }
        startRun.run();
        return "Robot " + (i + 1) + " of " + a.name() + " is now " + t.name() + named
                + "; its run started afresh in the main window (Edit > Undo there takes the old robot back)";
    }

    /**
     * How the arena names the robot: a bundled robot by its name, a saved one by its file; one with
     * unsaved changes by a copy in a temporary file (saved and tried again, the arena names its file).
     */
    private RobotKind kind(RobotType t, Path file) {
        for (RobotType b : bundled) {
            if (b.equals(t)) {
                return new RobotKind(t.name(), t);
            }
        }
        Path f = file;
        if (f == null) {
            try {
                f = java.nio.file.Files.createTempFile("robot-" + t.name() + "-", "." + RobotEditor.EXTENSION);
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException("cannot write the robot to a temporary file: " + e.getMessage()
                        + "; save it, then Try in arena", e);
            }
            f.toFile().deleteOnExit();
            store.save(t, f);
        }
        return new RobotKind(f.toAbsolutePath().toString(), t);
    }
}
