package org.kheperasim.sim.gui;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunRecording;

/**
 * Recordings: File > Save run recording (the folder that replays a run exactly, with its trace),
 * and File > Open recording, which replays a recording, a trace or a real robot's robot-link
 * recording in the window until Close replay brings the arena back.
 */
final class RecordingActions {
    private final JFrame frame;
    private final EditorModel model;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunChoices choices;
    private final ArenaFileActions files;
    private final RunControls runs;
    private final ServeControls serve;
    private final ReplayPlayer player;
    private final ViewFeed feed;
    private final Runnable fit;
    private EditorModel.Kept arenaBefore;
    private Path fileBefore;

    RecordingActions(JFrame frame, EditorModel model, ConsolePanel console, StatusBar status, RunChoices choices,
            ArenaFileActions files, RunControls runs, ServeControls serve, ReplayPlayer player, ViewFeed feed, Runnable fit) {
        this.frame = frame;
        this.model = model;
        this.console = console;
        this.status = status;
        this.choices = choices;
        this.files = files;
        this.runs = runs;
        this.serve = serve;
        this.player = player;
        this.feed = feed;
        this.fit = fit;
    }

    void saveRecording() {
        PacedRunner r = runs.runner();
        JFileChooser c = files.chooser(null, null);
        c.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        c.setDialogTitle("Folder for the run recording");
        if (r == null || c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path dir = c.getSelectedFile().toPath();
        save(r, choices.classpath, runs.runSettings(), dir);
        Path trace = runs.runTrace();
        if (trace != null) {
            try {
                // Whole lines, written at least once a second: the run up to about its last second.
                AtomicFiles.write(dir.resolve("run.trace"), Files.readString(trace));
            } catch (IOException e) {
                console.error("the recording has no run.trace: " + e.getMessage());
            }
        }
        status.show("Recording saved in " + dir + " (replay it with File > Open recording; check it with 'verify " + dir + "')", false);
    }

    /** Save what replays a run exactly (see {@link RunRecording}). */
    static void save(PacedRunner r, List<Path> classpath, Settings settings, Path dir) {
        RunRecording.save(r.session(), r.latest().timeSeconds(), classpath, settings, dir);
    }

    void openRecording() {
        JFileChooser c = files.chooser(null, null);
        c.setFileSelectionMode(JFileChooser.FILES_AND_DIRECTORIES);
        c.setDialogTitle("A run recording folder, a trace, or a robot-link recording");
        if (c.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            openRecording(c.getSelectedFile().toPath());
        }
    }

    /**
     * Opens a recording. Nothing of the arena being edited is lost, so nothing is asked: it is kept
     * aside, unsaved changes, undo steps and all, and Close replay brings it back as it was (a
     * Discard asked for here once brought the edits back unmarked, and the next Ctrl+Q lost them).
     *
     * @param path a recording folder, trace or robot-link recording
     * @return true when it opened
     */
    boolean openRecording(Path path) {
        long t0 = System.nanoTime();
        Replay replay;
        try {
            replay = ReplayFiles.open(path);
        } catch (IllegalArgumentException | UncheckedIOException e) {
            console.error(e.getMessage());
            JOptionPane.showMessageDialog(frame, e.getMessage(), "Cannot replay", JOptionPane.ERROR_MESSAGE);
            return false;
        }
        double ms = (System.nanoTime() - t0) / 1e6;
        serve.stop();
        runs.discard();
        if (!player.open()) {
            arenaBefore = model.keep();
            fileBefore = choices.arenaFile;
        }
        player.load(replay);
        feed.show(player);
        replay.notes().forEach(console::note);
        console.note(String.format(Locale.ROOT, "Replaying %s: %d robot(s), %.1f s of run, %d samples (read in %.0f ms)."
                + " Play, scrub the timeline, step; Close replay goes back to the arena.", path, replay.robotCount(),
                replay.endSeconds() - replay.startSeconds(), replay.samples(), ms));
        fit.run();
        return true;
    }

    /** @return true while a replay hides an arena with unsaved changes */
    boolean hidesUnsavedEdits() {
        return player.open() && arenaBefore != null && arenaBefore.dirty();
    }

    /** Leave the replay: the arena shown before comes back. */
    void closeReplay() {
        if (!player.open()) {
            return;
        }
        player.unload();
        feed.back(player);
        if (arenaBefore != null) {
            model.restore(arenaBefore);
            choices.arenaFile = fileBefore;
            arenaBefore = null;
        }
        console.note("Replay closed." + (model.dirty() ? " The arena " + model.arena().name() + " is back as it was, with"
                + " its unsaved changes." : ""));
        fit.run();
    }
}
