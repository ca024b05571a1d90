package org.kheperasim.sim.gui;

import java.awt.GridLayout;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.prefs.Preferences;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.JTextField;
import javax.swing.SpinnerNumberModel;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.run.SettingsFile;

/**
 * The arena's files: New, Open (an .arena or a WSU world), Save, Save as, the recent files, and
 * the prompt that keeps unsaved edits from being lost.
 */
final class ArenaFileActions {
    private static final int RECENT = 8;

    private final JFrame frame;
    private final EditorModel model;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunChoices choices;
    private final Preferences prefs;
    private final Runnable loaded;
    private final JMenu recentMenu = new JMenu("Open recent");

    /** @param loaded called after another arena was loaded (discard the run, fit the view) */
    ArenaFileActions(JFrame frame, EditorModel model, ConsolePanel console, StatusBar status, RunChoices choices,
            Preferences prefs, Runnable loaded) {
        this.frame = frame;
        this.model = model;
        this.console = console;
        this.status = status;
        this.choices = choices;
        this.prefs = prefs;
        this.loaded = loaded;
        rebuildRecent();
    }

    /** @return the File > Open recent menu */
    JMenu recentMenu() {
        return recentMenu;
    }

    /** @param ext an extension, or null @param what its description @return a chooser in the arena's folder */
    JFileChooser chooser(String ext, String what) {
        Path f = choices.arenaFile;
        JFileChooser c = new JFileChooser(f != null ? f.toAbsolutePath().getParent().toFile() : new File("."));
        if (ext != null) {
            c.setFileFilter(new FileNameExtensionFilter(what, ext));
        }
        return c;
    }

    void newArena() {
        JTextField name = new JTextField("arena", 12);
        JSpinner w = new JSpinner(new SpinnerNumberModel(1219.2, 100.0, 20000.0, 10.0));
        JSpinner h = new JSpinner(new SpinnerNumberModel(1219.2, 100.0, 20000.0, 10.0));
        JPanel p = new JPanel(new GridLayout(3, 2, 4, 4));
        p.add(new JLabel("Name"));
        p.add(name);
        p.add(new JLabel("Width, mm"));
        p.add(w);
        p.add(new JLabel("Height, mm"));
        p.add(h);
        if (JOptionPane.showConfirmDialog(frame, p, "New arena", JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION
                || !mayLeaveEdits("making a new arena")) {
            return;
        }
        Arena a = ArenaEdits.blank(name.getText().strip(), ((Number) w.getValue()).doubleValue(),
                ((Number) h.getValue()).doubleValue());
        choices.arenaFile = null;
        model.load(a);
        loaded.run();
    }

    /**
     * With unsaved arena edits: Save (then go on), Discard, or Cancel.
     *
     * @param doing what the user is about to do, e.g. "closing"
     * @return true when the window may go on (saved, discarded, or nothing to save)
     */
    boolean mayLeaveEdits(String doing) {
        if (!model.dirty()) {
            return true;
        }
        Object[] options = {"Save", "Discard", "Cancel"};
        int choice = JOptionPane.showOptionDialog(frame,
                "The arena " + model.arena().name() + " has unsaved changes. Save"
                + " them before " + doing + "?", "Unsaved changes", JOptionPane.YES_NO_CANCEL_OPTION,
                JOptionPane.WARNING_MESSAGE, null, options, options[0]);
        if (choice == 0) {
            save(false);
            return !model.dirty();
        }
        return choice == 1;
    }

    void open() {
        JFileChooser c = chooser("arena", "Arena files (.arena)");
        if (c.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            open(c.getSelectedFile().toPath());
        }
    }

    /** @param file an arena file to open (a bad one is refused; nothing loaded is lost) */
    void open(Path file) {
        if (!mayLeaveEdits("opening " + file.getFileName())) {
            return;
        }
        Arena a;
        try {
            a = ArenaFiles.load(file, console::note); // .arena text or a WSU world
        } catch (RuntimeException e) {
            console.error(e.getMessage());
            JOptionPane.showMessageDialog(frame, e.getMessage(), "Cannot open the arena", JOptionPane.ERROR_MESSAGE);
            return;
        }
        choices.arenaFile = file;
        model.load(a);
        Path s = SettingsFile.besideArena(file);
        if (Files.isRegularFile(s)) {
            choices.settings = SettingsFile.load(s);
            console.note("Settings loaded from " + s + ": " + choices.settings.describe());
        }
        remember(file);
        loaded.run();
    }

    /** @param as ask for a new name even when the arena has a file */
    void save(boolean as) {
        Path target = choices.arenaFile;
        // A WSU world file is never overwritten with text: saving one asks for a new .arena name.
        if (as || target == null || ArenaFiles.isWsuWorld(target)) {
            JFileChooser c = chooser("arena", "Arena files (.arena)");
            c.setSelectedFile(new File(model.arena().name() + ArenaFormat.EXTENSION));
            if (c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
                return;
            }
            target = c.getSelectedFile().toPath();
            if (!target.getFileName().toString().endsWith(ArenaFormat.EXTENSION)) {
                target = target.resolveSibling(target.getFileName() + ArenaFormat.EXTENSION);
            }
        }
        ArenaFormat.save(model.arena(), target);
        choices.arenaFile = target;
        if (!choices.settings.overrides().isEmpty()) {
            SettingsFile.save(choices.settings, SettingsFile.besideArena(target));
        }
        model.markSaved();
        remember(target);
        status.show("Saved " + target, false);
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
            item.addActionListener(e -> open(Path.of(s)));
            recentMenu.add(item);
        }
        recentMenu.setEnabled(recentMenu.getItemCount() > 0);
    }
}
