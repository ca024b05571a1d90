package org.kheperasim.sim.gui;

import java.awt.Toolkit;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.prefs.Preferences;
import javax.swing.Action;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.SettingsFile;
import org.kheperasim.sim.serve.ProtocolServer;

/**
 * The simulator's window (the paper's Figure 2): the arena view with its editing palette, the
 * sensor panel, the plot, the console, run controls and speed, and the recorder's bar while a run
 * is replayed. This class only puts the parts together and paints on a Swing timer; each part
 * ({@link RunControls}, {@link ServeControls}, {@link ReplayPlayer}, {@link ArenaFileActions},
 * {@link ControllerChooser}, {@link RecordingActions}, {@link WindowCommands}, {@link WindowMenus},
 * {@link StatusBar}) has one job, and the panels draw whatever {@link ViewFeed} shows.
 */
public final class MainWindow {
    private final JFrame frame = new JFrame();
    private final Preferences prefs = Preferences.userNodeForPackage(MainWindow.class);
    private final RunChoices choices = new RunChoices();
    private final EditorModel model;
    private final EditGestures gestures;
    private final ConsolePanel console = new ConsolePanel();
    private final StatusBar status = new StatusBar();
    private final WindowActions actions = new WindowActions(console, status);
    private final PlotPanel plot = new PlotPanel();
    private final RobotSelection robotSelection = new RobotSelection();
    private final RobotControllers robotControllers = new RobotControllers();
    private final RunControls runs;
    private final ServeControls serve;
    private final ReplayPlayer player;
    private final ReplayBar replayBar;
    private final ViewFeed feed;
    private final ArenaView arenaView;
    private final SensorPanel sensorPanel;
    private final SensorColumn sensorColumn;
    private final ControllerChooser controllers;
    private final WindowCommands commands;
    private final WindowMenus menus;
    private final ArenaFileActions files;
    private final RecordingActions recordings;
    private final org.kheperasim.sim.gui.robot.RobotEditing robotEditing;
    private FramePainter painter;
    private WindowKeys windowKeys;

    MainWindow(GuiOptions options) {
        Arena arena = ArenaFormat.resolve(options.arena());
        if (options.robotFile() != null) {
            arena = arena.withDefaultRobot(org.kheperasim.sim.arena.RobotKind.of(options.robotFile()));
        }
        Path maybeFile = Path.of(options.arena());
        choices.arenaFile = Files.isRegularFile(maybeFile) ? maybeFile : null;
        if (choices.arenaFile != null && Files.isRegularFile(SettingsFile.besideArena(choices.arenaFile))) {
            choices.settings = SettingsFile.load(SettingsFile.besideArena(choices.arenaFile));
        }
        // A .java to compile is named by its class from the start (the compile below confirms it).
        choices.controllerName = options.javaSource() != null
                ? options.javaSource().getFileName().toString().replaceFirst("\\.java$", "") : options.controller();
        choices.classpath.addAll(options.classpath());
        choices.seed = options.seed();
        choices.trusted = options.trusted();
        model = new EditorModel(arena);
        gestures = new EditGestures(model);
        runs = new RunControls(model, console, status, choices, robotControllers, this::runChanged);
        feed = new ViewFeed(runs, robotSelection);
        serve = new ServeControls(model, console, status, choices, feed);
        player = new ReplayPlayer(model);
        arenaView = new ArenaView(model, gestures, feed::snapshot, feed::trails, robotSelection);
        arenaView.setEditable(() -> !player.open());
        sensorPanel = new SensorPanel(feed::selected, feed::state);
        sensorColumn = new SensorColumn(sensorPanel, feed::selectedVision);
        controllers = new ControllerChooser(frame, console, status, choices, robotControllers,
                robotSelection, runs::discard);
        runs.checks(controllers::readyForNewRun, controllers::staleNote);
        files = new ArenaFileActions(frame, model, console, status, choices, prefs, () -> {
            runs.discard();
            arenaView.fit();
            arenaOpened();
        });
        recordings = new RecordingActions(frame, model, console, status, choices, files, runs, serve,
                player, feed, () -> {
                    arenaView.fit();
                    actions.refresh();
                });
        replayBar = new ReplayBar(player, () -> actions.get("closeReplay").actionPerformed(null));
        commands = new WindowCommands(actions, frame, model, console, choices, runs, serve, player, controllers);
        commands.build(files, recordings, () -> close(files), this::setTool, arenaView);
        actions.onRefresh(() -> {
            commands.refresh();
            frame.setTitle(title());
        });
        robotEditing = new org.kheperasim.sim.gui.robot.RobotEditing(frame, model, robotSelection::index,
                runs::discard, () -> {
            runs.start();
            actions.refresh();
        }, new org.kheperasim.sim.gui.robot.RobotFiles(), org.kheperasim.sim.gui.robot.RobotFiles.bundled());
        actions.add("editRobot", "Edit robot…", "the selected robot's type in the robot editor", null,
                robotEditing::editSelected);
        actions.add("openRobot", "Open robot file…", "a robot file in the robot editor", null, robotEditing::openFile);
        actions.add("newRobot", "New robot…", "design a robot from scratch in the robot editor", null,
                robotEditing::newRobot);
        menus = new WindowMenus(actions, runs::setSpeed);
        wireModel();
        frame.setJMenuBar(menus.menuBar(files.recentMenu(), model, menus.viewMenu(arenaView),
                menus.trustToggle(choices, console)));
        frame.setContentPane(
                WindowLayout.content(frame, menus.toolbar(controllers.box()), arenaView, replayBar.component(),
                sensorColumn, plot, console, status.component(), () -> model.arena().width() / model.arena().height()));
        frame.setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close(files);
            }
        });
        windowKeys = commands.bindKeys(frame);
        frame.setBounds(WindowSize.fit(prefs.getInt("width", 1180), prefs.getInt("height", 900)));
        setTool(Tool.SELECT);
        actions.refresh();
        console.note("Loaded arena " + arena.name() + "; controller " + choices.controllerName
                + ". Press Start (F5). Draw with the palette; File > Open recording replays a run; Help > Quick start"
                + " gets your own controller running in 15 minutes.");
        painter = new FramePainter(feed, player, replayBar, plot, sensorColumn, arenaView, console,
                status, runs, choices);
        if (options.javaSource() != null) {
            controllers.compileAndUse(options.javaSource());
            actions.refresh();
        }
    }

    /** Another arena was opened: its robots are not the last arena's, so none keeps a controller of its own. */
    private void arenaOpened() {
        Arena arena = model.arena();
        String own = robotControllers.describe(Integer.MAX_VALUE);
        robotControllers.clear();
        int n = arena.robots().size();
        console.note("Opened arena " + arena.name() + " (" + n + (n == 1 ? " robot" : " robots")
                + "); every robot runs "
                + choices.controllerName
                + (own.isEmpty() ? "" : " (the last arena's own choices, " + own + ", are dropped)"));
    }

    private void wireModel() {
        console.clock(() -> {
            Snapshot now = feed.snapshot();
            return now == null ? 0 : now.timeNanos();
        });
        robotSelection.onChange(() -> SwingUtilities.invokeLater(() -> {
            forgetPainted();
            sensorColumn.repaint();
            arenaView.repaint();
        }));
        model.onChange(arenaView::repaint);
        model.onChange(actions::refresh);
        model.onRefusal(m -> {
            // The whole reason in the console too: the status bar may be too narrow for it.
            console.error("refused: " + m);
            status.show("Refused: " + m, true);
            arenaView.repaint();
            Toolkit.getDefaultToolkit().beep();
        });
        model.onEdit(edited -> {
            runs.forwardEdit(edited);
            frame.setTitle(title());
        });
        model.setRun(() -> runs.active() ? runs.runner().session().arena() : null, runs::liveRobots);
        status.onExpire(gestures::clearRefusal);
        console.onControllerError(runs::controllerError);
    }

    private String title() {
        return "Khepera simulator - " + (player.open() ? "replay of " + player.replay().source() : model.arena().name()
                + (model.dirty() ? " *" : "")
                + (choices.arenaFile != null ? " (" + choices.arenaFile + ")" : " (bundled)")
                + " - " + choices.controllerName);
    }

    private void forgetPainted() {
        if (painter != null) {
            painter.forget();
        }
    }

    private void runChanged() {
        forgetPainted();
        sensorColumn.repaint();
        arenaView.repaint();
        actions.refresh();
    }

    void setTool(Tool t) {
        gestures.setTool(t);
        menus.showTool(t);
        status.show(switch (t) {
            case SELECT -> "Select: click or drag a box; drag to move; drag a wall's end to resize; drag a robot's"
                    + " handle to turn; [ ] rotate; Delete.";
            case WALL -> "Wall: press and drag to draw a wall (snaps to the 10 mm grid and to wall ends).";
            case LIGHT -> "Light: click to place a lamp.";
            case CAP -> "Cap: click to place a bottle cap.";
            case ROBOT -> "Robot start: press where the robot starts, drag to aim it.";
        }, false);
    }

    private void close(ArenaFileActions files) {
        if (recordings.hidesUnsavedEdits()) {
            // The arena under the replay is what would be lost: show it, then ask.
            recordings.closeReplay();
        }
        if (!files.mayLeaveEdits("closing")) {
            return;
        }
        prefs.putInt("width", frame.getWidth());
        prefs.putInt("height", frame.getHeight());
        painter.stop();
        if (windowKeys != null) {
            windowKeys.uninstall();
        }
        serve.stop();
        runs.close();
        frame.dispose();
    }

    // ---- for tests and drivers ----

    /** @return the frame */
    public JFrame frame() {
        return frame;
    }

    /** @param key an action's key, e.g. {@code start} @return the action */
    public Action action(String key) {
        return actions.get(key);
    }

    /** @return frames per second the arena view painted over the last second */
    public double fps() {
        return painter.fps();
    }

    Snapshot snapshot() {
        return feed.snapshot();
    }

    /** @return the robot the sensor panel shows */
    RobotView shownRobot() {
        return feed.selected();
    }

    /** @return the protocol server of the first robot while the window serves, else null */
    public ProtocolServer server() {
        List<ProtocolServer> s = serve.servers();
        return s.isEmpty() ? null : s.get(0);
    }

    /** @return the protocol servers while the window serves, one per robot */
    public List<ProtocolServer> servers() {
        return serve.servers();
    }

    /** @return the runner, or null */
    public PacedRunner runner() {
        return runs.runner();
    }

    /** @return the editor model */
    public EditorModel model() {
        return model;
    }

    /** @return the arena view's mapping from mm to pixels */
    public ViewTransform view() {
        return arenaView.view();
    }

    /** @return the arena view component */
    public JComponent arenaComponent() {
        return arenaView;
    }

    /** @return the console's text */
    public String consoleText() {
        console.drain();
        return console.contents();
    }

    /** @return the replay player (tests) */
    ReplayPlayer player() {
        return player;
    }

    /** @param path a recording folder, trace or robot-link recording @return true when it opened (tests) */
    boolean openRecording(Path path) {
        boolean ok = recordings.openRecording(path);
        actions.refresh();
        return ok;
    }

    /** @return the status bar (tests) */
    StatusBar status() {
        return status;
    }

    /** @return the live run's score now, or null without a run or without tasks (tests) */
    org.kheperasim.sim.task.Score score() {
        return runs.scoreNow();
    }

    /** @return the Robot menu's editors (tests) */
    org.kheperasim.sim.gui.robot.RobotEditing robotEditing() {
        return robotEditing;
    }

    /** @return the plot (tests) */
    PlotPanel plot() {
        return plot;
    }

    /** @param file an arena file to open */
    void openArena(Path file) {
        files.open(file);
    }

    /** @param source compile it and make it the controller @return true if it compiled */
    boolean compileAndUse(Path source) {
        return controllers.compileAndUse(source);
    }

    /** @param s the settings for the next run */
    void setSettings(Settings s) {
        choices.settings = s;
    }

    /** @param factor one of the offered speeds, as the speed box would choose it (event thread) */
    public void chooseSpeed(double factor) {
        menus.chooseSpeed(factor);
    }

    /** @return the controller the next run uses */
    public String controllerName() {
        return choices.controllerName;
    }

    /** @param s the seed for the next run */
    public void setSeed(long s) {
        choices.seed = s;
    }

    /** Start or resume (tests). */
    void start() {
        runs.start();
        actions.refresh();
    }

    /** Save what replays a run exactly (tests). */
    static void saveRecording(PacedRunner r, List<Path> classpath, Settings settings, Path dir) {
        RecordingActions.save(r, classpath, settings, dir);
    }
}
