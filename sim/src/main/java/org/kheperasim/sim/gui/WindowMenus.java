package org.kheperasim.sim.gui;

import java.awt.event.KeyEvent;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.DoubleConsumer;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.run.PacedRunner;

/** The window's menu bar and toolbar, built from its {@link WindowActions}. */
final class WindowMenus {
    /** Speeds offered, simulated seconds per real second; the last is as fast as possible. */
    static final double[] SPEEDS = {0.25, 0.5, 1, 2, 4, PacedRunner.MAX_SPEED};

    /** Room between the toolbar's groups, px: narrow, so that the toolbar fits one row on a 1180 px window. */
    private static final java.awt.Dimension SEPARATOR = new java.awt.Dimension(9, 20);

    private final WindowActions actions;
    private final JComboBox<String> speedBox = new JComboBox<>();
    private final Map<Tool, JToggleButton> toolButtons = new LinkedHashMap<>();

    /** @param setSpeed what choosing a speed does */
    WindowMenus(WindowActions actions, DoubleConsumer setSpeed) {
        this.actions = actions;
        for (double s : SPEEDS) {
            // The toolbar's box is kept narrow ("fastest"); the Run > Speed menu says it in full.
            speedBox.addItem(s == PacedRunner.MAX_SPEED ? "fastest" : speedLabel(s));
        }
        speedBox.setToolTipText(
                "simulated seconds per real second; fastest = as fast as possible. The speed never changes"
                + " what the run computes");
        speedBox.setSelectedIndex(2);
        speedBox.setName("speed");
        speedBox.setFocusable(false);
        speedBox.addActionListener(e -> setSpeed.accept(SPEEDS[speedBox.getSelectedIndex()]));
    }

    /** @param factor one of {@link #SPEEDS}, chosen as the box would */
    void chooseSpeed(double factor) {
        for (int i = 0; i < SPEEDS.length; i++) {
            if (SPEEDS[i] == factor) {
                speedBox.setSelectedIndex(i);
                return;
            }
        }
        throw new IllegalArgumentException("speed " + factor + " is not offered");
    }

    /** @param t the tool whose button shows as chosen */
    void showTool(Tool t) {
        JToggleButton b = toolButtons.get(t);
        if (b != null) {
            b.setSelected(true);
        }
    }

    JMenuBar menuBar(JMenu recent, EditorModel model, JMenu viewOptions, JCheckBoxMenuItem trust) {
        JMenuBar bar = new JMenuBar();
        JMenu file = menu("File", KeyEvent.VK_F, "new", "open");
        file.add(recent);
        file.addSeparator();
        addAll(file, "save", "saveAs");
        file.addSeparator();
        addAll(file, "openRecording", "saveRecording", "exportPage", "closeReplay");
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
        bar.add(viewOptions);
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
        controllerMenu.add(trust);
        bar.add(controllerMenu);
        bar.add(menu("Robot", KeyEvent.VK_B, "editRobot", "openRobot", "newRobot"));
        bar.add(menu("Settings", KeyEvent.VK_S, "settings"));
        bar.add(menu("Help", KeyEvent.VK_H, "quickStart", "manual"));
        return bar;
    }

    /** @param arenaView the view whose drawing options the menu toggles @return the View menu */
    JMenu viewMenu(ArenaView arenaView) {
        JMenu view = menu("View", KeyEvent.VK_V, "zoomIn", "zoomOut", "fit");
        view.addSeparator();
        String[] labels = {"Sensor beams", "Trail", "Grid", "Start poses during a run"};
        for (int i = 0; i < labels.length; i++) {
            int which = i;
            ArenaRenderer.Options o = arenaView.options();
            boolean[] on = {o.beams(), o.trail(), o.grid(), o.startPoses()};
            JCheckBoxMenuItem item = new JCheckBoxMenuItem(labels[i], on[i]);
            item.addActionListener(e -> {
                ArenaRenderer.Options c = arenaView.options();
                boolean v = item.isSelected();
                arenaView.setOptions(new ArenaRenderer.Options(which == 0 ? v : c.beams(), which == 1 ? v : c.trail(),
                        which == 2 ? v : c.grid(), which == 3 ? v : c.startPoses()));
            });
            view.add(item);
        }
        return view;
    }

    /** @return Controller > Trust this controller */
    JCheckBoxMenuItem trustToggle(RunChoices choices, ConsolePanel console) {
        JCheckBoxMenuItem trust = new JCheckBoxMenuItem(
                "Trust this controller (your own code: run it unchecked, with files, network and its own windows)",
                choices.trusted);
        trust.setToolTipText(
                "uncontained: only for code you trust; see docs/controller-rules.md. Takes effect at the next Start.");
        trust.addActionListener(e -> {
            choices.trusted = trust.isSelected();
            console.note(choices.trusted ? "the controller will run uncontained (trusted) from the next Start"
                    : "the controller will run contained from the next Start");
        });
        return trust;
    }

    JToolBar toolbar(JComboBox<String> controllers) {
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        // Wraps onto a second row on a narrow window: the controller box at its end stays on screen.
        bar.setLayout(new WrapLayout());
        ButtonGroup group = new ButtonGroup();
        for (Tool t : Tool.values()) {
            JToggleButton b = new JToggleButton(actions.get("tool." + t.name()));
            b.setName("tool." + t.name());
            b.setFocusable(false);
            group.add(b);
            toolButtons.put(t, b);
            bar.add(b);
        }
        bar.addSeparator(SEPARATOR);
        for (String k : new String[] {"undo", "redo", "delete"}) {
            bar.add(button(k));
        }
        bar.addSeparator(SEPARATOR);
        for (String k : new String[] {"start", "pause", "step", "stop", "reset"}) {
            bar.add(button(k));
        }
        bar.addSeparator(SEPARATOR);
        bar.add(new JLabel("Speed "));
        bar.add(speedBox);
        bar.addSeparator(SEPARATOR);
        bar.add(new JLabel("Controller "));
        bar.add(controllers);
        return bar;
    }

    private JButton button(String key) {
        JButton b = new JButton(actions.get(key));
        b.setName(key);
        b.setFocusable(false);
        return b;
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

    static String speedLabel(double s) {
        if (s == PacedRunner.MAX_SPEED) {
            return "as fast as possible";
        }
        return s == StrictMath.rint(s) ? "x" + (int) s : "x" + s;
    }
}
