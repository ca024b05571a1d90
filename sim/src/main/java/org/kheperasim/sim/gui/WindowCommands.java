package org.kheperasim.sim.gui;

import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.Map;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.JComponent;
import javax.swing.KeyStroke;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.run.PacedRunner;

/**
 * Every command of the window as an action, wired to the part that does it, and which of them are
 * enabled in the window's state (running, serving, replaying, what the editor has selected).
 */
final class WindowCommands {
    private final WindowActions actions;
    private final JFrame frame;
    private final EditorModel model;
    private final ConsolePanel console;
    private final RunChoices choices;
    private final RunControls runs;
    private final ServeControls serve;
    private final ReplayPlayer player;
    private final ControllerChooser controllers;

    WindowCommands(WindowActions actions, JFrame frame, EditorModel model, ConsolePanel console, RunChoices choices,
            RunControls runs, ServeControls serve, ReplayPlayer player, ControllerChooser controllers) {
        this.actions = actions;
        this.frame = frame;
        this.model = model;
        this.console = console;
        this.choices = choices;
        this.runs = runs;
        this.serve = serve;
        this.player = player;
        this.controllers = controllers;
    }

    /**
     * @param close what Close window does
     * @param setTool what choosing a tool does
     * @param view the arena view (zoom, fit)
     */
    void build(ArenaFileActions files, RecordingActions recordings, Runnable close,
            java.util.function.Consumer<Tool> setTool,
            ArenaView view) {
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        int shift = InputEvent.SHIFT_DOWN_MASK;
        add("new", "New arena…", "a new empty arena of a chosen size", KeyEvent.VK_N, ctrl, files::newArena);
        add("open", "Open arena…", "open an .arena file or a WSU world", KeyEvent.VK_O, ctrl, files::open);
        add("save", "Save", "save the arena (atomically)", KeyEvent.VK_S, ctrl, () -> files.save(false));
        add("saveAs", "Save as…", "save the arena under a new name", KeyEvent.VK_S, ctrl | shift,
                () -> files.save(true));
        add("openRecording", "Open recording…", "replay a run recording folder, a trace or a real robot's robot-link"
                + " recording: play, pause, scrub, step", KeyEvent.VK_R, ctrl | shift, recordings::openRecording);
        add("saveRecording", "Save run recording…",
                "save what replays this run exactly: start arena, edits, seed, trace",
                0, 0, recordings::saveRecording);
        add("exportPage", "Export run as web page…",
                "write the run shown (live or replayed) as one web page that replays"
                + " it in any browser: no Java, server or network needed (docs/web-replay.md)", 0, 0,
                recordings::exportPage);
        add("closeReplay", "Close replay", "back to the arena and its runs", 0, 0, recordings::closeReplay);
        add("close", "Close window", "close the simulator", KeyEvent.VK_Q, ctrl, close);
        add("undo", "Undo", "undo the last edit", KeyEvent.VK_Z, ctrl, model::undo);
        add("redo", "Redo", "redo the edit undone", KeyEvent.VK_Y, ctrl, model::redo);
        add("delete", "Delete", "delete the selected walls, lamps and caps", 0, 0, model::deleteSelection);
        add("selectAll", "Select all", "select everything", KeyEvent.VK_A, ctrl,
                () -> model.select(ArenaEdits.inside(model.arena(), -1e9, -1e9, 1e9, 1e9)));
        add("rotateLeft", "Rotate left 15°", "rotate the selection counter-clockwise", 0, 0,
                () -> model.rotateSelection(15));
        add("rotateRight", "Rotate right 15°", "rotate the selection clockwise", 0, 0,
                () -> model.rotateSelection(-15));
        add("start", "Start", "start or resume the run", KeyEvent.VK_F5, 0, runs::start);
        add("pause", "Pause", "pause the run", KeyEvent.VK_F6, 0, runs::pause);
        add("step", "Step", "run " + PacedRunner.STEP_NANOS / 1_000_000 + " ms of simulated time, then pause",
                KeyEvent.VK_F7, 0, runs::step);
        add("stop", "Stop", "stop the run (the robot stops where it is)", KeyEvent.VK_F8, 0, runs::stop);
        add("reset", "Reset", "back to the start poses, reloading the controller class", KeyEvent.VK_F9,
                0, runs::reset);
        add("serve", "Serve this robot", "let a Khepera client (robot-link, a C program, MATLAB) drive a simulated"
                + " robot in this arena over TCP with the robot's own protocol", 0, 0, () -> {
                    if (!serve.serving()) {
                        runs.discard();
                    }
                    serve.toggle();
                });
        add("loadClasses", "Load compiled classes…", "add a folder or jar with your compiled controller", 0, 0,
                controllers::loadClasses);
        add("openJava", "Open .java…", "compile a controller source file and use it", 0, 0, controllers::openJava);
        add("assignRobot", "Give the selected robot this controller",
                "from the next Start the selected robot (click it)"
                + " runs the controller chosen now; the others keep theirs", 0, 0, controllers::assignSelected);
        add("clearRobots", "Every robot runs the chosen controller",
                "forget the controllers given to single robots", 0, 0,
                controllers::clearAssignments);
        add("reload", "Reload controller", "recompile the .java (if one was opened) and reset, picking up your changes",
                KeyEvent.VK_F10, 0, controllers::reload);
        add("settings", "Settings…", "sensors, motors, light, link, seed", 0, 0, this::showSettings);
        add("seed", "Seed…", "the run's seed (a new random one by default)", 0, 0, this::askSeed);
        add("zoomIn", "Zoom in", "zoom in", KeyEvent.VK_EQUALS, ctrl, () -> view.zoom(1.25));
        add("zoomOut", "Zoom out", "zoom out", KeyEvent.VK_MINUS, ctrl, () -> view.zoom(0.8));
        add("fit", "Fit arena", "show the whole arena", KeyEvent.VK_0, ctrl, view::fit);
        add("manual", "Manual", "the manual", KeyEvent.VK_F1, 0, () -> HelpDialog.show(frame, "gui.md"));
        add("quickStart", "Quick start", "the first hour", 0, 0, () -> HelpDialog.show(frame, "quick-start.md"));
        for (Tool t : Tool.values()) {
            add("tool." + t.name(), t.label(), t.label() + " tool (" + t.key() + ")", 0, 0, () -> setTool.accept(t));
        }
    }

    private void add(String key, String name, String tip, int code, int mods, Runnable body) {
        actions.add(key, name, tip, code == 0 ? null : WindowActions.ks(code, mods), body);
    }

    /** Enable what the window's state allows. */
    void refresh() {
        PacedRunner.State s = runs.runState();
        boolean running = s == PacedRunner.State.RUNNING;
        boolean live = runs.active();
        boolean serving = serve.serving();
        boolean replaying = player.open();
        boolean editing = !replaying;
        Action serveAction = actions.get("serve");
        serveAction.putValue(Action.NAME, serving ? "Stop serving" : "Serve this robot");
        serveAction.setEnabled((!live || serving) && editing);
        actions.enable("start", !running && !serving && editing);
        actions.enable("pause", running);
        actions.enable("step", !running && !serving && editing && s != PacedRunner.State.FINISHED
                && s != PacedRunner.State.STOPPED && s != PacedRunner.State.TIME_UP);
        actions.enable("stop", live);
        actions.enable("reset", s != null);
        actions.enable("saveRecording", s != null);
        actions.enable("exportPage", s != null || replaying);
        actions.enable("closeReplay", replaying);
        actions.enable("undo", editing && model.canUndo());
        actions.enable("redo", editing && model.canRedo());
        boolean selected = editing && !model.selection().isEmpty();
        actions.enable("delete", selected);
        actions.enable("rotateLeft", selected);
        actions.enable("rotateRight", selected);
        actions.enable("new", !live && editing);
        actions.enable("open", !live && editing);
        actions.enable("save", editing);
        actions.enable("saveAs", editing);
        actions.enable("reload", controllers.canReload() || s != null);
        controllers.box().setEnabled(!live);
    }

    /** @param frame the window @return the run keys, installed (F5..F10 and Space wherever the focus is) */
    WindowKeys bindKeys(JFrame frame) {
        JComponent root = frame.getRootPane();
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_DELETE, 0), "delete");
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_BACK_SPACE, 0), "delete");
        bind(root, KeyStroke.getKeyStroke('['), "rotateLeft");
        bind(root, KeyStroke.getKeyStroke(']'), "rotateRight");
        Action startPause = new AbstractAction() {
            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                startOrPause();
            }
        };
        // F5..F10 and Space work wherever the focus is (split panes take F6/F8, the menu bar F10).
        // The palette's letters too: the console (a text pane) would take them otherwise.
        Map<Integer, Action> letters = new java.util.HashMap<>();
        for (Tool t : Tool.values()) {
            letters.put(KeyEvent.getExtendedKeyCodeForChar(t.key().charAt(0)), actions.get("tool." + t.name()));
        }
        return WindowKeys.install(frame, Map.of(KeyEvent.VK_F5, actions.get("start"), KeyEvent.VK_F6,
                actions.get("pause"), KeyEvent.VK_F7, actions.get("step"), KeyEvent.VK_F8, actions.get("stop"),
                KeyEvent.VK_F9, actions.get("reset"), KeyEvent.VK_F10, actions.get("reload")), startPause, letters);
    }

    private void bind(JComponent c, KeyStroke k, String key) {
        c.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(k, key);
        c.getActionMap().put(key, actions.get(key));
    }

    /** Space: play or pause whatever is shown (the replay, else the run). */
    void startOrPause() {
        if (player.open()) {
            player.toggle();
            return;
        }
        Action a = runs.runState() == PacedRunner.State.RUNNING ? actions.get("pause") : actions.get("start");
        if (a.isEnabled()) {
            a.actionPerformed(null);
        }
    }

    private void showSettings() {
        SettingsDialog.Result r = SettingsDialog.show(frame, choices.settings, choices.arenaFile);
        if (r != null) {
            choices.settings = r.settings();
            console.note("Settings: " + choices.settings.describe()
                    + (runs.active() ? " (they apply from the next Reset or Start)" : ""));
        }
    }

    private void askSeed() {
        String s = JOptionPane.showInputDialog(frame, "Seed for the next run (empty = a new random seed each run):",
                choices.seed == null ? "" : choices.seed.toString());
        if (s != null) {
            choices.seed = s.isBlank() ? null : Long.parseLong(s.strip());
        }
    }
}
