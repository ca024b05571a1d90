package org.kheperasim.sim.gui;

import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.prefs.Preferences;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JSpinner;
import javax.swing.JSplitPane;
import javax.swing.JTextField;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SpinnerNumberModel;
import javax.swing.Timer;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.RobotView;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.engine.Snapshot;
import org.kheperasim.sim.host.ControllerHost;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.ControllerCompiler;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.serve.ProtocolServer;
import org.kheperasim.sim.serve.ServedArena;
import org.kheperasim.sim.serve.ServedRobot;
import org.kheperasim.sim.run.RunRecording;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.run.SettingsFile;
import org.kheperasim.sim.run.Simulation;

/**
 * The simulator's window (the paper's Figure 2): the arena view with its editing palette, the
 * sensor panel, a rolling plot, the console, run controls and speed. One {@link Action} per
 * command, shared by menu, toolbar and keys; their enabled state follows the run's state.
 *
 * <p>The run itself lives on a {@link PacedRunner}'s thread; the window only reads its latest
 * snapshot on a Swing timer and sends it commands, so the engine never waits on the screen.
 */
public final class MainWindow {
    private static final System.Logger LOG = System.getLogger(MainWindow.class.getName());

    /** Speeds offered, simulated seconds per real second; the last is as fast as possible. */
    static final double[] SPEEDS = {0.25, 0.5, 1, 2, 4, PacedRunner.MAX_SPEED};
    /** Frame period while paced, ms: a little faster than 60 frames/s, so the screen keeps up. */
    private static final int FRAME_MS = 12;
    /**
     * Frame period at full speed, ms: the engine and the controller thread want both cores then,
     * and 25 frames/s is plenty to watch a robot race.
     */
    private static final int FRAME_MS_MAX_SPEED = 40;
    private static final int RECENT = 8;

    private final JFrame frame = new JFrame();
    private final EditorModel model;
    private final EditGestures gestures;
    private final TrailRecorder trail = new TrailRecorder();
    private final ConsolePanel console = new ConsolePanel();
    private final PlotPanel plot = new PlotPanel();
    private final ArenaView arenaView;
    private final SensorPanel sensorPanel;
    private final RobotSelection robotSelection = new RobotSelection();
    private final RobotControllers robotControllers = new RobotControllers();
    private WindowKeys windowKeys;
    /** The trace the current run writes, or null. */
    private volatile Path runTrace;
    private final JLabel message = new JLabel(" ");
    private final JLabel position = new JLabel(" ");
    private final JLabel clock = new JLabel(" ");
    private final JComboBox<String> controllers = new JComboBox<>();
    private final JComboBox<String> speedBox = new JComboBox<>();
    private final Map<String, Action> actions = new LinkedHashMap<>();
    private final Map<Tool, JToggleButton> toolButtons = new LinkedHashMap<>();
    private final JMenu recentMenu = new JMenu("Open recent");
    private final Preferences prefs = Preferences.userNodeForPackage(MainWindow.class);
    private final Timer timer;

    private Path arenaFile;
    private Settings settings = Settings.defaults();
    private Long seed;
    private String controllerName;
    private List<Path> classpath;
    private Path javaSource;
    private double speed = 1;
    private Settings runSettings = Settings.defaults();
    private volatile PacedRunner runner;
    /** Run the controller uncontained (Controller > Trust this controller); off by default. */
    private boolean trusted;
    // "Serve this robot": a simulated robot answering the Khepera protocol over TCP, in real time.
    private volatile ServedArena served;
    /** One protocol server per robot of the served arena. */
    private final List<ProtocolServer> servers = new ArrayList<>();
    private final java.util.concurrent.atomic.AtomicReference<Snapshot> servedLatest =
            new java.util.concurrent.atomic.AtomicReference<>();
    private Snapshot lastPainted;
    private long fpsFrames;
    private long fpsSince = System.nanoTime();
    private double fps;
    private long messageUntil;

    MainWindow(GuiOptions options) {
        Arena arena = ArenaFormat.resolve(options.arena());
        Path maybeFile = Path.of(options.arena());
        arenaFile = Files.isRegularFile(maybeFile) ? maybeFile : null;
        if (arenaFile != null && Files.isRegularFile(SettingsFile.besideArena(arenaFile))) {
            settings = SettingsFile.load(SettingsFile.besideArena(arenaFile));
        }
        model = new EditorModel(arena);
        gestures = new EditGestures(model);
        controllerName = options.controller();
        classpath = new ArrayList<>(options.classpath());
        seed = options.seed();
        arenaView = new ArenaView(model, gestures, this::snapshot, this::trails, robotSelection);
        sensorPanel = new SensorPanel(() -> robotSelection.in(snapshot()), this::runState);
        console.clock(() -> {
            Snapshot now = snapshot();
            return now == null ? 0 : now.timeNanos();
        });
        robotSelection.onChange(() -> javax.swing.SwingUtilities.invokeLater(() -> {
            plot.clear();
            sensorPanel.repaint();
            arenaView.repaint();
        }));
        model.onChange(arenaView::repaint);
        model.onChange(this::updateActions);
        model.onRefusal(m -> {
            showMessage("Refused: " + m, true);
            java.awt.Toolkit.getDefaultToolkit().beep();
        });
        model.onEdit(this::forwardEdit);
        model.setRun(() -> active() ? runner.session().arena() : null,
                () -> runner == null ? List.of() : runner.latest().robots());

        buildActions();
        frame.setJMenuBar(menus());
        frame.setTitle(title());
        frame.setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close();
            }
        });
        JPanel right = new JPanel(new BorderLayout());
        right.add(sensorPanel, BorderLayout.NORTH);
        right.add(plot, BorderLayout.CENTER);
        JSplitPane top = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, arenaView, right);
        top.setResizeWeight(1);
        console.setPreferredSize(new Dimension(900, 150));
        JSplitPane main = new JSplitPane(JSplitPane.VERTICAL_SPLIT, top, console);
        main.setResizeWeight(1);
        // However small the screen, the console (compile errors, stack traces) opens 150 px tall.
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowOpened(WindowEvent e) {
                main.setDividerLocation(StrictMath.max(200, main.getHeight() - main.getDividerSize() - 150));
            }
        });
        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar(), BorderLayout.NORTH);
        content.add(main, BorderLayout.CENTER);
        content.add(statusBar(), BorderLayout.SOUTH);
        frame.setContentPane(content);
        keys();
        frame.setBounds(WindowSize.fit(prefs.getInt("width", 1180), prefs.getInt("height", 900)));
        setTool(Tool.SELECT);
        updateActions();
        console.note("Loaded arena " + arena.name() + "; controller " + controllerName
                + ". Press Start (F5). Draw with the palette; Help > Quick start explains the first hour.");
        timer = new Timer(FRAME_MS, e -> tick());
        timer.start();
    }

    /** @return the frame */
    public JFrame frame() {
        return frame;
    }

    // ---- state read by the panels (event thread) ----

    Snapshot snapshot() {
        if (served != null) {
            return servedLatest.get();
        }
        PacedRunner r = runner;
        return r == null ? null : r.latest();
    }

    /** @return the run's state in words: running, paused, stopped, finished, ready, serving; null with no run */
    private String runState() {
        if (served != null) {
            return "serving";
        }
        PacedRunner r = runner;
        return r == null ? null : r.state().name().toLowerCase(Locale.ROOT);
    }

    /** @return the robot the sensor panel shows (tests) */
    RobotView shownRobot() {
        return robotSelection.in(snapshot());
    }

    private List<float[]> trails() {
        Snapshot s = snapshot();
        List<float[]> out = new ArrayList<>();
        if (s != null) {
            for (int i = 0; i < s.robots().size(); i++) {
                out.add(trail.trail(i));
            }
        }
        return out;
    }

    private boolean active() {
        PacedRunner r = runner;
        return r != null && (r.state() == PacedRunner.State.READY || r.state() == PacedRunner.State.RUNNING
                || r.state() == PacedRunner.State.PAUSED);
    }

    // ---- the frame timer ----

    private void tick() {
        console.drain();
        Snapshot s = snapshot();
        if (s != lastPainted) {
            plot.sample(s, robotSelection.index());
            sensorPanel.repaint();
            lastPainted = s;
        }
        arenaView.repaint();
        long now = System.nanoTime();
        if (now - fpsSince >= 1_000_000_000L) {
            long frames = arenaView.frames();
            fps = (frames - fpsFrames) * 1e9 / (now - fpsSince);
            fpsFrames = frames;
            fpsSince = now;
        }
        PacedRunner r = runner;
        String state = r == null ? "no run" : r.state().name().toLowerCase(Locale.ROOT);
        String rtf = r == null || r.state() != PacedRunner.State.RUNNING ? "-" : String.format(Locale.ROOT, "%.2fx", r.realTimeFactor());
        clock.setText(String.format(Locale.ROOT, "  %s   t = %.2f s   real-time factor %s   %.0f fps  ", state,
                s == null ? 0.0 : s.timeSeconds(), rtf, fps));
        double[] m = arenaView.mouse();
        position.setText(Double.isNaN(m[0]) ? "  " : String.format(Locale.ROOT, "  (%.1f, %.1f) mm  ", m[0], m[1]));
        if (messageUntil != 0 && now > messageUntil) {
            message.setText(" ");
            messageUntil = 0;
            gestures.clearRefusal();
        }
    }

    /** @return frames per second the arena view painted over the last second */
    public double fps() {
        return fps;
    }

    // ---- actions ----

    private Action action(String key, String name, String tip, KeyStroke accel, Runnable body) {
        Action a = new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                try {
                    body.run();
                } catch (RuntimeException ex) {
                    console.error(name + ": " + ex.getMessage());
                    showMessage(name + ": " + ex.getMessage(), true);
                }
                updateActions();
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, tip);
        if (accel != null) {
            a.putValue(Action.ACCELERATOR_KEY, accel);
        }
        actions.put(key, a);
        return a;
    }

    /** @param key an action's key, e.g. {@code start} @return the action (for tests and drivers) */
    public Action action(String key) {
        return actions.get(key);
    }

    private static KeyStroke ks(int code, int mods) {
        return KeyStroke.getKeyStroke(code, mods);
    }

    private void buildActions() {
        int ctrl = java.awt.Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        int shift = java.awt.event.InputEvent.SHIFT_DOWN_MASK;
        action("new", "New arena…", "a new empty arena of a chosen size", ks(KeyEvent.VK_N, ctrl), this::newArena);
        action("open", "Open arena…", "open an .arena file", ks(KeyEvent.VK_O, ctrl), this::openArena);
        action("save", "Save", "save the arena (atomically)", ks(KeyEvent.VK_S, ctrl), () -> save(false));
        action("saveAs", "Save as…", "save the arena under a new name", ks(KeyEvent.VK_S, ctrl | shift), () -> save(true));
        action("saveRecording", "Save run recording…", "save what replays this run exactly: start arena, edits, seed", null, this::saveRecording);
        action("close", "Close window", "close the simulator", ks(KeyEvent.VK_Q, ctrl), this::close);
        action("undo", "Undo", "undo the last edit", ks(KeyEvent.VK_Z, ctrl), model::undo);
        action("redo", "Redo", "redo the edit undone", ks(KeyEvent.VK_Y, ctrl), model::redo);
        action("delete", "Delete", "delete the selected walls, lamps and caps", null, model::deleteSelection);
        action("selectAll", "Select all", "select everything", ks(KeyEvent.VK_A, ctrl),
                () -> model.select(ArenaEdits.inside(model.arena(), -1e9, -1e9, 1e9, 1e9)));
        action("rotateLeft", "Rotate left 15°", "rotate the selection counter-clockwise", null, () -> model.rotateSelection(15));
        action("rotateRight", "Rotate right 15°", "rotate the selection clockwise", null, () -> model.rotateSelection(-15));
        action("start", "Start", "start or resume the run", ks(KeyEvent.VK_F5, 0), this::start);
        action("pause", "Pause", "pause the run", ks(KeyEvent.VK_F6, 0), () -> runner.pause());
        action("step", "Step", "run " + PacedRunner.STEP_NANOS / 1_000_000 + " ms of simulated time, then pause", ks(KeyEvent.VK_F7, 0), this::step);
        action("stop", "Stop", "stop the run (the robot stops where it is)", ks(KeyEvent.VK_F8, 0), this::stop);
        action("reset", "Reset", "back to the start poses, reloading the controller class", ks(KeyEvent.VK_F9, 0), this::reset);
        action("serve", "Serve this robot", "let a Khepera client (robot-link, a C program, MATLAB) drive a simulated"
                + " robot in this arena over TCP with the robot's own protocol", null, this::toggleServe);
        action("loadClasses", "Load compiled classes…", "add a folder or jar with your compiled controller", null, this::loadClasses);
        action("openJava", "Open .java…", "compile a controller source file and use it", null, this::openJava);
        action("assignRobot", "Give the selected robot this controller", "from the next Start the selected robot (click it)"
                + " runs the controller chosen now; the others keep theirs", null, () -> {
                    int i = robotSelection.index();
                    robotControllers.assign(i, controllerName);
                    console.note("robot " + i + " will run " + controllerName + " from the next Start");
                });
        action("clearRobots", "Every robot runs the chosen controller", "forget the controllers given to single robots", null,
                () -> {
                    robotControllers.clear();
                    console.note("every robot will run the controller chosen in the box from the next Start");
                });
        action("reload", "Reload controller", "recompile the .java (if one was opened) and reset, picking up your changes", ks(KeyEvent.VK_F10, 0), this::reload);
        action("settings", "Settings…", "sensors, motors, light, link, seed", null, this::showSettings);
        action("seed", "Seed…", "the run's seed (a new random one by default)", null, this::askSeed);
        action("zoomIn", "Zoom in", "zoom in", ks(KeyEvent.VK_EQUALS, ctrl), () -> arenaView.zoom(1.25));
        action("zoomOut", "Zoom out", "zoom out", ks(KeyEvent.VK_MINUS, ctrl), () -> arenaView.zoom(0.8));
        action("fit", "Fit arena", "show the whole arena", ks(KeyEvent.VK_0, ctrl), arenaView::fit);
        action("manual", "Manual", "the manual", ks(KeyEvent.VK_F1, 0), () -> HelpDialog.show(frame, "gui.md"));
        action("quickStart", "Quick start", "the first hour", null, () -> HelpDialog.show(frame, "quick-start.md"));
        for (Tool t : Tool.values()) {
            action("tool." + t.name(), t.label(), t.label() + " tool (" + t.key() + ")", null, () -> setTool(t));
        }
    }

    private void updateActions() {
        PacedRunner r = runner;
        PacedRunner.State s = r == null ? null : r.state();
        boolean running = s == PacedRunner.State.RUNNING;
        boolean live = active();
        boolean serving = served != null;
        actions.get("serve").putValue(Action.NAME, serving ? "Stop serving" : "Serve this robot");
        actions.get("serve").setEnabled(!live || serving);
        actions.get("start").setEnabled(!running && !serving);
        actions.get("pause").setEnabled(running);
        actions.get("step").setEnabled(!running && !serving && s != PacedRunner.State.FINISHED
                && s != PacedRunner.State.STOPPED);
        actions.get("stop").setEnabled(live);
        actions.get("reset").setEnabled(r != null);
        actions.get("saveRecording").setEnabled(r != null);
        actions.get("undo").setEnabled(model.canUndo());
        actions.get("redo").setEnabled(model.canRedo());
        actions.get("delete").setEnabled(!model.selection().isEmpty());
        actions.get("rotateLeft").setEnabled(!model.selection().isEmpty());
        actions.get("rotateRight").setEnabled(!model.selection().isEmpty());
        actions.get("new").setEnabled(!live);
        actions.get("open").setEnabled(!live);
        actions.get("reload").setEnabled(javaSource != null || !classpath.isEmpty() || r != null);
        controllers.setEnabled(!live);
        frame.setTitle(title());
    }

    private String title() {
        return "Khepera simulator - " + model.arena().name() + (model.dirty() ? " *" : "")
                + (arenaFile != null ? " (" + arenaFile + ")" : " (bundled)") + " - " + controllerName;
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = menu("File", KeyEvent.VK_F, "new", "open");
        file.add(recentMenu);
        rebuildRecent();
        file.addSeparator();
        addAll(file, "save", "saveAs", "saveRecording");
        file.addSeparator();
        addAll(file, "close");
        bar.add(file);
        JMenu edit = menu("Edit", KeyEvent.VK_E, "undo", "redo", "delete", "selectAll", "rotateLeft", "rotateRight");
        edit.addSeparator();
        for (Tool t : Tool.values()) {
            edit.add(new JMenuItem(actions.get("tool." + t.name())));
        }
        JCheckBoxMenuItem snap = new JCheckBoxMenuItem("Snap to grid and wall ends", model.snap());
        snap.addActionListener(e -> model.setSnap(snap.isSelected()));
        edit.addSeparator();
        edit.add(snap);
        bar.add(edit);
        JMenu view = menu("View", KeyEvent.VK_V, "zoomIn", "zoomOut", "fit");
        view.addSeparator();
        view.add(optionToggle("Sensor beams", 0));
        view.add(optionToggle("Trail", 1));
        view.add(optionToggle("Grid", 2));
        view.add(optionToggle("Start poses during a run", 3));
        bar.add(view);
        JMenu run = menu("Run", KeyEvent.VK_R, "start", "pause", "step", "stop", "reset");
        run.addSeparator();
        JMenu speeds = new JMenu("Speed");
        ButtonGroup group = new ButtonGroup();
        for (int i = 0; i < SPEEDS.length; i++) {
            int k = i;
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(speedLabel(SPEEDS[i]), SPEEDS[i] == 1);
            item.addActionListener(e -> speedBox.setSelectedIndex(k));
            group.add(item);
            speeds.add(item);
        }
        run.add(speeds);
        addAll(run, "seed");
        run.addSeparator();
        addAll(run, "serve");
        bar.add(run);
        JMenu controllerMenu = menu("Controller", KeyEvent.VK_C, "loadClasses", "openJava", "reload");
        controllerMenu.addSeparator();
        addAll(controllerMenu, "assignRobot", "clearRobots");
        controllerMenu.addSeparator();
        JCheckBoxMenuItem trust = new JCheckBoxMenuItem("Trust this controller (allow files, network, reflection)", trusted);
        trust.setToolTipText("uncontained: only for code you trust; see docs/controller-rules.md. Takes effect at the next Start.");
        trust.addActionListener(e -> {
            trusted = trust.isSelected();
            console.note(trusted ? "the controller will run uncontained (trusted) from the next Start"
                    : "the controller will run contained from the next Start");
        });
        controllerMenu.add(trust);
        bar.add(controllerMenu);
        bar.add(menu("Settings", KeyEvent.VK_S, "settings"));
        bar.add(menu("Help", KeyEvent.VK_H, "quickStart", "manual"));
        return bar;
    }

    private JCheckBoxMenuItem optionToggle(String label, int which) {
        ArenaRenderer.Options o = arenaView.options();
        boolean on = switch (which) {
            case 0 -> o.beams();
            case 1 -> o.trail();
            case 2 -> o.grid();
            default -> o.startPoses();
        };
        JCheckBoxMenuItem item = new JCheckBoxMenuItem(label, on);
        item.addActionListener(e -> {
            ArenaRenderer.Options c = arenaView.options();
            boolean v = item.isSelected();
            arenaView.setOptions(new ArenaRenderer.Options(which == 0 ? v : c.beams(), which == 1 ? v : c.trail(),
                    which == 2 ? v : c.grid(), which == 3 ? v : c.startPoses()));
        });
        return item;
    }

    private JMenu menu(String name, int mnemonic, String... keys) {
        JMenu m = new JMenu(name);
        m.setMnemonic(mnemonic);
        addAll(m, keys);
        return m;
    }

    private void addAll(JMenu m, String... keys) {
        for (String k : keys) {
            m.add(new JMenuItem(actions.get(k)));
        }
    }

    private static String speedLabel(double s) {
        if (s == PacedRunner.MAX_SPEED) {
            return "as fast as possible";
        }
        return s == StrictMath.rint(s) ? "x" + (int) s : "x" + s;
    }

    private JToolBar toolbar() {
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        ButtonGroup group = new ButtonGroup();
        for (Tool t : Tool.values()) {
            JToggleButton b = new JToggleButton(actions.get("tool." + t.name()));
            b.setName("tool." + t.name());
            b.setFocusable(false);
            group.add(b);
            toolButtons.put(t, b);
            bar.add(b);
        }
        bar.addSeparator();
        for (String k : new String[] {"undo", "redo", "delete"}) {
            bar.add(button(k));
        }
        bar.addSeparator();
        for (String k : new String[] {"start", "pause", "step", "stop", "reset"}) {
            bar.add(button(k));
        }
        bar.addSeparator();
        bar.add(new JLabel(" Speed "));
        for (double s : SPEEDS) {
            speedBox.addItem(speedLabel(s));
        }
        speedBox.setSelectedIndex(2);
        speedBox.setName("speed");
        speedBox.setMaximumSize(new Dimension(150, speedBox.getPreferredSize().height));
        speedBox.setFocusable(false);
        speedBox.addActionListener(e -> setSpeed(SPEEDS[speedBox.getSelectedIndex()]));
        bar.add(speedBox);
        bar.addSeparator();
        bar.add(new JLabel(" Controller "));
        for (String c : ControllerCatalog.bundled()) {
            controllers.addItem(c);
        }
        if (((javax.swing.DefaultComboBoxModel<String>) controllers.getModel()).getIndexOf(controllerName) < 0) {
            controllers.addItem(controllerName);
        }
        controllers.setSelectedItem(controllerName);
        controllers.setName("controller");
        controllers.setMaximumSize(new Dimension(160, controllers.getPreferredSize().height));
        controllers.addActionListener(e -> {
            Object sel = controllers.getSelectedItem();
            if (sel != null && !sel.equals(controllerName)) {
                controllerName = sel.toString();
                discardRun();
                console.note("Controller " + controllerName + " chosen; press Start.");
                updateActions();
            }
        });
        bar.add(controllers);
        return bar;
    }

    private JButton button(String key) {
        JButton b = new JButton(actions.get(key));
        b.setName(key);
        b.setFocusable(false);
        return b;
    }

    private JComponent statusBar() {
        JPanel bar = new JPanel(new BorderLayout());
        bar.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        message.setName("message");
        clock.setName("clock");
        bar.add(message, BorderLayout.CENTER);
        JPanel east = new JPanel(new FlowLayout(FlowLayout.RIGHT, 0, 0));
        east.add(position);
        east.add(clock);
        bar.add(east, BorderLayout.EAST);
        return bar;
    }

    private void keys() {
        JComponent root = frame.getRootPane();
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_DELETE, 0), "delete");
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_BACK_SPACE, 0), "delete");
        bind(root, KeyStroke.getKeyStroke('['), "rotateLeft");
        bind(root, KeyStroke.getKeyStroke(']'), "rotateRight");
        Action startPause = new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                Action a = runner != null && runner.state() == PacedRunner.State.RUNNING ? actions.get("pause") : actions.get("start");
                if (a.isEnabled()) {
                    a.actionPerformed(e);
                }
            }
        };
        // F5..F10 and Space work wherever the focus is (split panes take F6/F8, the menu bar F10).
        windowKeys = WindowKeys.install(frame, Map.of(KeyEvent.VK_F5, actions.get("start"), KeyEvent.VK_F6,
                actions.get("pause"), KeyEvent.VK_F7, actions.get("step"), KeyEvent.VK_F8, actions.get("stop"),
                KeyEvent.VK_F9, actions.get("reset"), KeyEvent.VK_F10, actions.get("reload")), startPause);
        for (Tool t : Tool.values()) {
            bind(root, KeyStroke.getKeyStroke(t.key().charAt(0)), "tool." + t.name());
            bind(root, KeyStroke.getKeyStroke(Character.toLowerCase(t.key().charAt(0))), "tool." + t.name());
        }
    }

    private void bind(JComponent c, KeyStroke k, String key) {
        c.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(k, key);
        if (actions.containsKey(key)) {
            c.getActionMap().put(key, actions.get(key));
        }
    }

    void setTool(Tool t) {
        gestures.setTool(t);
        JToggleButton b = toolButtons.get(t);
        if (b != null) {
            b.setSelected(true);
        }
        showMessage(switch (t) {
            case SELECT -> "Select: click or drag a box; drag to move; drag a wall's end to resize; drag a robot's handle to turn; [ ] rotate; Delete.";
            case WALL -> "Wall: press and drag to draw a wall (snaps to the 10 mm grid and to wall ends).";
            case LIGHT -> "Light: click to place a lamp.";
            case CAP -> "Cap: click to place a bottle cap.";
            case ROBOT -> "Robot start: press where the robot starts, drag to aim it.";
        }, false);
    }

    private void showMessage(String text, boolean error) {
        message.setText(text);
        message.setForeground(error ? new Color(0xC00000) : Color.DARK_GRAY);
        messageUntil = error ? System.nanoTime() + 6_000_000_000L : 0;
        arenaView.repaint();
    }

    // ---- running ----

    private void setSpeed(double s) {
        speed = s;
        timer.setDelay(s == PacedRunner.MAX_SPEED ? FRAME_MS_MAX_SPEED : FRAME_MS);
        PacedRunner r = runner;
        if (r != null) {
            r.setSpeed(s);
        }
    }

    private boolean ensureRunner() {
        PacedRunner r = runner;
        if (r != null && active()) {
            return true;
        }
        if (r != null) {
            r.stop();
        }
        long runSeed = seed != null ? seed : Simulation.randomSeed();
        RunSession session;
        try {
            session = new RunSession(model.arena(), robotControllers.setups(model.arena().robots().size(), controllerName,
                    settings), new ControllerCatalog(classpath, trusted), runSeed, console, ControllerHost.Options.defaults());
        } catch (RuntimeException e) {
            console.error("cannot start " + controllerName + ": " + e.getMessage());
            showMessage("Cannot start: " + e.getMessage(), true);
            return false;
        }
        runSettings = settings;
        keepTrace(session);
        trail.clear();
        plot.clear();
        session.addListener(trail, 20 * Engine.TICK_NANOS);
        String own = robotControllers.describe(model.arena().robots().size());
        console.note("Run of " + controllerName + (own.isEmpty() ? "" : " (" + own + ")") + " in " + model.arena().name() + ", seed " + runSeed
                + (settings.overrides().isEmpty() ? "" : ", settings " + settings.describe()));
        PacedRunner next = new PacedRunner(session, st -> javax.swing.SwingUtilities.invokeLater(this::stateChanged));
        next.setSpeed(speed);
        runner = next;
        return true;
    }

    private void stateChanged() {
        PacedRunner r = runner;
        if (r != null && r.state() == PacedRunner.State.FINISHED) {
            console.note("The controller ended at t = " + String.format(Locale.ROOT, "%.3f s", r.latest().timeSeconds()) + ".");
        }
        if (r != null && r.failure() != null) {
            console.error("the run failed: " + r.failure());
        }
        updateActions();
    }

    /** Start or resume. */
    void start() {
        if (ensureRunner()) {
            runner.start();
        }
    }

    private void step() {
        if (ensureRunner()) {
            runner.step();
        }
    }

    private void stop() {
        PacedRunner r = runner;
        if (r != null) {
            r.stop();
            console.note("Stopped at t = " + String.format(Locale.ROOT, "%.3f s", r.latest().timeSeconds())
                    + "; Reset to go back to the start, or Start for a new run.");
        }
    }

    private void reset() {
        discardRun();
        console.note("Reset: the robot is back at its start; the controller is loaded afresh at Start.");
    }

    private void discardRun() {
        PacedRunner r = runner;
        runner = null;
        if (r != null) {
            r.stop();
        }
        trail.clear();
        plot.clear();
        lastPainted = null;
        sensorPanel.repaint();
        arenaView.repaint();
    }

    private void forwardEdit(Arena edited) {
        PacedRunner r = runner;
        if (r != null && active()) {
            r.edit(edited);
        }
        frame.setTitle(title());
    }

    /**
     * Serve a simulated robot in the arena as drawn over the Khepera protocol on a free loopback
     * port, or stop serving. The robot runs in real time with its own engine; the window draws it.
     */
    private void toggleServe() {
        if (served != null) {
            stopServing();
            return;
        }
        if (active()) {
            stop();
        }
        long serveSeed = seed != null ? seed : Simulation.randomSeed();
        ServedArena world = new ServedArena(model.arena(), settings, serveSeed, 1.0);
        world.addListener(servedLatest::set, 20 * Engine.TICK_NANOS);
        try {
            for (ServedRobot robot : world.robots()) {
                servers.add(ProtocolServer.start(robot, 0));
            }
        } catch (java.io.IOException e) {
            servers.forEach(ProtocolServer::close);
            servers.clear();
            world.close();
            console.error("Cannot serve the robots: " + e.getMessage() + ". Free a loopback port or use 'khepera-sim serve --port N'.");
            return;
        }
        served = world;
        for (int i = 0; i < servers.size(); i++) {
            String who = servers.size() == 1 ? "server: " : "server of robot " + i + ": ";
            servers.get(i).addListener(ev -> console.note(who + ev.text()));
        }
        String urls = servers.size() == 1 ? servers.get(0).url()
                : String.join(", ", servers.stream().map(ProtocolServer::url).toList());
        console.note((servers.size() == 1 ? "Serving this robot at " : "Serving these " + servers.size()
                + " robots (robot 0, 1, ...) at ") + urls + " (seed " + serveSeed + "). Drive "
                + (servers.size() == 1 ? "it" : "each") + " with any Khepera client, e.g. java -jar"
                + " robot-link/target/khepera-link.jar run --port " + servers.get(0).url()
                + " --controller WallFollower. Run > Stop serving ends it.");
        showMessage("Serving at " + urls, false);
        updateActions();
    }

    private void stopServing() {
        ServedArena r = served;
        served = null;
        servers.forEach(ProtocolServer::close);
        servers.clear();
        if (r != null) {
            r.close();
        }
        console.note("Stopped serving; the robots' wheels were stopped.");
        showMessage("Stopped serving", false);
        updateActions();
    }

    /** @return the protocol server of the first robot while the window serves, else null (for tests and drivers) */
    public ProtocolServer server() {
        return servers.isEmpty() ? null : servers.get(0);
    }

    /** @return the protocol servers while the window serves, one per robot (for tests and drivers) */
    public List<ProtocolServer> servers() {
        return List.copyOf(servers);
    }

    /** @return the runner, or null (for tests and drivers) */
    public PacedRunner runner() {
        return runner;
    }

    /** @return the editor model (for tests and drivers) */
    public EditorModel model() {
        return model;
    }

    /** @return the arena view's mapping from mm to pixels (for drivers) */
    public ViewTransform view() {
        return arenaView.view();
    }

    /** @return the arena view component (for drivers) */
    public JComponent arenaComponent() {
        return arenaView;
    }

    /** @return the console's text (for tests and drivers) */
    public String consoleText() {
        console.drain();
        return console.contents();
    }

    // ---- files ----

    private JFileChooser chooser(String ext, String what) {
        JFileChooser c = new JFileChooser(arenaFile != null ? arenaFile.toAbsolutePath().getParent().toFile() : new java.io.File("."));
        if (ext != null) {
            c.setFileFilter(new FileNameExtensionFilter(what, ext));
        }
        return c;
    }

    private void newArena() {
        JTextField name = new JTextField("arena", 12);
        JSpinner w = new JSpinner(new SpinnerNumberModel(1219.2, 100.0, 20000.0, 10.0));
        JSpinner h = new JSpinner(new SpinnerNumberModel(1219.2, 100.0, 20000.0, 10.0));
        JPanel p = new JPanel(new java.awt.GridLayout(3, 2, 4, 4));
        p.add(new JLabel("Name"));
        p.add(name);
        p.add(new JLabel("Width, mm"));
        p.add(w);
        p.add(new JLabel("Height, mm"));
        p.add(h);
        if (JOptionPane.showConfirmDialog(frame, p, "New arena", JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION) {
            return;
        }
        if (!confirmDiscard()) {
            return;
        }
        Arena a = ArenaEdits.blank(name.getText().strip(), ((Number) w.getValue()).doubleValue(), ((Number) h.getValue()).doubleValue());
        discardRun();
        arenaFile = null;
        model.load(a);
        arenaView.fit();
    }

    /**
     * Before the window closes with unsaved arena edits: Save (then close), Discard, or Cancel.
     *
     * @return true when the window may go on (saved, discarded, or nothing to save)
     */
    private boolean mayLeaveEdits(String doing) {
        if (!model.dirty()) {
            return true;
        }
        Object[] options = {"Save", "Discard", "Cancel"};
        int choice = JOptionPane.showOptionDialog(frame, "The arena " + model.arena().name() + " has unsaved changes. Save"
                + " them before " + doing + "?", "Unsaved changes", JOptionPane.YES_NO_CANCEL_OPTION,
                JOptionPane.WARNING_MESSAGE, null, options, options[0]);
        if (choice == 0) {
            save(false);
            return !model.dirty();
        }
        return choice == 1;
    }

    private boolean confirmDiscard() {
        return !model.dirty() || JOptionPane.showConfirmDialog(frame, "The arena has unsaved changes. Discard them?", "Unsaved changes",
                JOptionPane.YES_NO_OPTION) == JOptionPane.YES_OPTION;
    }

    private void openArena() {
        JFileChooser c = chooser("arena", "Arena files (.arena)");
        if (c.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            openArena(c.getSelectedFile().toPath());
        }
    }

    /** @param file an arena file to open (a bad one is refused; nothing loaded is lost) */
    void openArena(Path file) {
        if (!confirmDiscard()) {
            return;
        }
        Arena a;
        try {
            a = org.kheperasim.sim.arena.ArenaFiles.load(file, console::note); // .arena text or a WSU world
        } catch (RuntimeException e) {
            console.error(e.getMessage());
            JOptionPane.showMessageDialog(frame, e.getMessage(), "Cannot open the arena", JOptionPane.ERROR_MESSAGE);
            return;
        }
        discardRun();
        arenaFile = file;
        model.load(a);
        Path s = SettingsFile.besideArena(file);
        if (Files.isRegularFile(s)) {
            settings = SettingsFile.load(s);
            console.note("Settings loaded from " + s + ": " + settings.describe());
        }
        remember(file);
        arenaView.fit();
    }

    private void save(boolean as) {
        Path target = arenaFile;
        // A WSU world file is never overwritten with text: saving one asks for a new .arena name.
        if (as || target == null || org.kheperasim.sim.arena.ArenaFiles.isWsuWorld(target)) {
            JFileChooser c = chooser("arena", "Arena files (.arena)");
            c.setSelectedFile(new java.io.File(model.arena().name() + ArenaFormat.EXTENSION));
            if (c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
                return;
            }
            target = c.getSelectedFile().toPath();
            if (!target.getFileName().toString().endsWith(ArenaFormat.EXTENSION)) {
                target = target.resolveSibling(target.getFileName() + ArenaFormat.EXTENSION);
            }
        }
        ArenaFormat.save(model.arena(), target);
        arenaFile = target;
        if (!settings.overrides().isEmpty()) {
            SettingsFile.save(settings, SettingsFile.besideArena(target));
        }
        model.markSaved();
        remember(target);
        showMessage("Saved " + target, false);
    }

    private void remember(Path file) {
        List<String> list = recent();
        list.remove(file.toAbsolutePath().toString());
        list.add(0, file.toAbsolutePath().toString());
        while (list.size() > RECENT) {
            list.remove(list.size() - 1);
        }
        prefs.put("recent", String.join("\n", list));
        rebuildRecent();
    }

    private List<String> recent() {
        List<String> out = new ArrayList<>();
        for (String s : prefs.get("recent", "").split("\n")) {
            if (!s.isBlank()) {
                out.add(s);
            }
        }
        return out;
    }

    private void rebuildRecent() {
        recentMenu.removeAll();
        for (String s : recent()) {
            JMenuItem item = new JMenuItem(s);
            item.addActionListener(e -> openArena(Path.of(s)));
            recentMenu.add(item);
        }
        recentMenu.setEnabled(recentMenu.getItemCount() > 0);
    }

    private void saveRecording() {
        PacedRunner r = runner;
        JFileChooser c = chooser(null, null);
        c.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        c.setDialogTitle("Folder for the run recording");
        if (c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path dir = c.getSelectedFile().toPath();
        saveRecording(r, classpath, runSettings, dir);
        Path trace = runTrace;
        if (trace != null) {
            try {
                // Whole lines, written at least once a second: the run up to about its last second.
                org.kheperasim.sim.files.AtomicFiles.write(dir.resolve("run.trace"), Files.readString(trace));
            } catch (java.io.IOException e) {
                console.error("the recording has no run.trace: " + e.getMessage());
            }
        }
        showMessage("Recording saved in " + dir + " (see replay.txt; check it with 'verify " + dir + "')", false);
    }

    /**
     * Every run of the window keeps its trace (100 ms samples) in a temporary file, so that a run
     * recording holds what the run did, for {@code verify}.
     */
    private void keepTrace(RunSession session) {
        try {
            Path file = Files.createTempFile("khepera-window-run-", ".trace");
            file.toFile().deleteOnExit();
            session.trace(org.kheperasim.sim.trace.LineFileWriter.open(file), 100);
            runTrace = file;
        } catch (java.io.IOException e) {
            runTrace = null;
            console.note("this run keeps no trace (" + e.getMessage() + "); a recording of it cannot be verified");
        }
    }

    /** Save what replays a run exactly (see {@link RunRecording}), with the run's trace so far. */
    static void saveRecording(PacedRunner r, List<Path> classpath, Settings settings, Path dir) {
        RunRecording.save(r.session(), r.latest().timeSeconds(), classpath, settings, dir);
    }

    private void close() {
        if (!mayLeaveEdits("closing")) {
            return;
        }
        prefs.putInt("width", frame.getWidth());
        prefs.putInt("height", frame.getHeight());
        timer.stop();
        if (windowKeys != null) {
            windowKeys.uninstall();
        }
        if (served != null) {
            stopServing();
        }
        PacedRunner r = runner;
        runner = null;
        if (r != null) {
            r.stop();
        }
        frame.dispose();
    }

    // ---- controllers ----

    private void loadClasses() {
        JFileChooser c = chooser(null, null);
        c.setFileSelectionMode(JFileChooser.FILES_AND_DIRECTORIES);
        c.setDialogTitle("A folder with your .class files, or a jar");
        if (c.showOpenDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path p = c.getSelectedFile().toPath();
        String guess = guessClass(p);
        String name = JOptionPane.showInputDialog(frame, "The controller's class name (with its package, if any):", guess);
        if (name == null || name.isBlank()) {
            return;
        }
        useController(List.of(p), name.strip(), null);
    }

    private static String guessClass(Path p) {
        if (Files.isDirectory(p)) {
            try (var files = Files.walk(p, 4)) {
                return files.filter(f -> f.toString().endsWith(".class") && !f.getFileName().toString().contains("$"))
                        .map(f -> p.relativize(f).toString().replace(java.io.File.separatorChar, '.').replaceFirst("\\.class$", ""))
                        .findFirst().orElse("Robot");
            } catch (IOException e) {
                LOG.log(System.Logger.Level.DEBUG, "cannot look for classes in " + p + ", guessing Robot: " + e);
                return "Robot";
            }
        }
        return "Robot";
    }

    private void useController(List<Path> cp, String name, Path source) {
        try {
            new ControllerCatalog(cp).load(name);
        } catch (RuntimeException e) {
            console.error(e.getMessage());
            showMessage("Cannot use " + name + ": " + e.getMessage(), true);
            return;
        }
        classpath = new ArrayList<>(cp);
        javaSource = source;
        controllerName = name;
        discardRun();
        if (((javax.swing.DefaultComboBoxModel<String>) controllers.getModel()).getIndexOf(name) < 0) {
            controllers.addItem(name);
        }
        controllers.setSelectedItem(name);
        console.note("Controller " + name + " loaded from " + cp + ". Press Start.");
    }

    private void openJava() {
        JFileChooser c = chooser("java", "Java source (.java)");
        if (c.showOpenDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        compileAndUse(c.getSelectedFile().toPath());
    }

    /** @param source compile it and make it the controller @return true if it compiled */
    boolean compileAndUse(Path source) {
        ControllerCompiler.Result result;
        try {
            Path out = Path.of(System.getProperty("user.home"), ".khepera-sim", "classes",
                    source.getFileName().toString().replaceFirst("\\.java$", "") + "-" + Long.toHexString(System.nanoTime()));
            result = ControllerCompiler.compile(source, out);
        } catch (IOException | RuntimeException e) {
            console.error("cannot compile " + source + ": " + e.getMessage());
            showMessage("Cannot compile: " + e.getMessage(), true);
            return false;
        }
        if (!result.success()) {
            console.error("compiling " + source.getFileName() + " failed:\n" + result.report(source.toString()));
            showMessage("Compile errors in " + source.getFileName() + ": see the console (line numbers given)", true);
            javaSource = source;
            updateActions();
            return false;
        }
        if (!result.problems().isEmpty()) {
            console.note(result.report(source.toString()));
        }
        console.note("Compiled " + source.getFileName() + " into " + result.classes());
        useController(List.of(result.classes()), result.className(), source);
        return true;
    }

    private void reload() {
        if (javaSource != null) {
            compileAndUse(javaSource);
        } else {
            discardRun();
            console.note("Reloaded: the controller class is read afresh at Start.");
        }
    }

    // ---- settings ----

    private void showSettings() {
        SettingsDialog.Result r = SettingsDialog.show(frame, settings, arenaFile);
        if (r != null) {
            settings = r.settings();
            console.note("Settings: " + settings.describe() + (active() ? " (they apply from the next Reset or Start)" : ""));
        }
    }

    private void askSeed() {
        String s = JOptionPane.showInputDialog(frame, "Seed for the next run (empty = a new random seed each run):",
                seed == null ? "" : seed.toString());
        if (s == null) {
            return;
        }
        seed = s.isBlank() ? null : Long.parseLong(s.strip());
    }

    /** @param s the settings for the next run (for tests and drivers) */
    void setSettings(Settings s) {
        settings = s;
    }

    /** @param factor one of the offered speeds, as the speed box would choose it (event thread) */
    public void chooseSpeed(double factor) {
        for (int i = 0; i < SPEEDS.length; i++) {
            if (SPEEDS[i] == factor) {
                speedBox.setSelectedIndex(i);
                return;
            }
        }
        throw new IllegalArgumentException("speed " + factor + " is not offered");
    }

    /** @return the controller the next run uses */
    public String controllerName() {
        return controllerName;
    }

    /** @param s the seed for the next run */
    public void setSeed(long s) {
        seed = s;
    }
}
