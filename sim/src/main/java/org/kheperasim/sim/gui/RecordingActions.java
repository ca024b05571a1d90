package org.kheperasim.sim.gui;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.host.HostedController;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunRecording;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.trace.LineFileWriter;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPage;

/**
 * Recordings: File > Save run recording (the folder that replays a run exactly, with its trace),
 * File > Open recording, which replays a recording, a trace or a real robot's robot-link recording in
 * the window until Close replay brings the arena back, and File > Export run as web page, which
 * writes the run shown (live or replayed) as one page that replays it in any browser.
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
    private Replay shown;

    RecordingActions(JFrame frame, EditorModel model, ConsolePanel console, StatusBar status, RunChoices choices,
            ArenaFileActions files, RunControls runs, ServeControls serve, ReplayPlayer player,
            ViewFeed feed, Runnable fit) {
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
        status.show("Recording saved in " + dir + " (replay it with File > Open recording; check it with 'verify "
                + dir + "')", false);
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
        shown = replay;
        feed.show(player);
        replay.notes().forEach(console::note);
        console.note(String.format(Locale.ROOT,
                "Replaying %s: %d robot(s), %.1f s of run, %d samples (read in %.0f ms)."
                + " Play, scrub the timeline, step; Close replay goes back to the arena.", path, replay.robotCount(),
                replay.endSeconds() - replay.startSeconds(), replay.samples(), ms));
        fit.run();
        return true;
    }

    void exportPage() {
        JFileChooser c = files.chooser("html", "Web pages (.html)");
        c.setDialogTitle("Save the run as a web page (one file that replays it in any browser)");
        c.setSelectedFile(c.getCurrentDirectory().toPath().resolve("run.html").toFile());
        if (c.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) {
            Path out = c.getSelectedFile().toPath();
            exportPage(out.getFileName().toString().contains(".") ? out
                    : out.resolveSibling(out.getFileName() + ".html"));
        }
    }

    /**
     * Writes the page of the run shown: the replay open, else the window's run so far (from its
     * start arena, its edits and its trace, as a run recording holds them), with its failures and,
     * once it is paused or ended, its own score.
     *
     * @param out the page to write
     * @return true when it was written
     */
    boolean exportPage(Path out) {
        try {
            RunPage.Written w;
            if (player.open() && shown != null) {
                w = RunPage.write(shown, RunOutcome.none(), out);
            } else if (runs.runner() != null && runs.runTrace() != null) {
                w = ofRun(runs.runner(), choices.classpath, runs.runSettings(), runs.runTrace(), out);
            } else {
                status.show("No run to export: start a run, or open a recording, first", true);
                return false;
            }
            String what = String.format(Locale.ROOT,
                    "Web page saved: %s (%.0f KB, %.1f s of the run; open it in any browser)",
                    w.file(), w.bytes() / 1024.0, w.seconds());
            console.note(what);
            status.show(what, false);
            return true;
        } catch (IllegalArgumentException | IllegalStateException | UncheckedIOException e) {
            console.error("cannot export the run as a web page: " + e.getMessage());
            JOptionPane.showMessageDialog(frame, e.getMessage(), "Cannot export the run", JOptionPane.ERROR_MESSAGE);
            return false;
        }
    }

    /**
     * The page of the window's run so far: the recording that replays it (start arena, edits, trace:
     * its whole lines, flushed now) read back, with its title, its failed controllers (the student's
     * line where one threw) and, unless it is running, the engine's own facts for the score.
     */
    private static RunPage.Written ofRun(PacedRunner r, List<Path> classpath, Settings settings, Path trace, Path out) {
        Path dir;
        try {
            dir = Files.createTempDirectory("khepera-page-");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot make a temporary folder: " + e.getMessage(), e);
        }
        try {
            save(r, classpath, settings, dir);
            LineFileWriter.flushAll();
            AtomicFiles.write(dir.resolve("run.trace"), Files.readAllBytes(trace));
            RunSession session = r.session();
            List<RunOutcome.Failure> failed = new ArrayList<>();
            for (int i = 0; i < session.hosts().size(); i++) {
                HostedController h = session.hosts().get(i);
                if (h.status().failed()) {
                    Throwable t = h.failure();
                    String where = t == null ? null : RunMessages.studentLine(t);
                    failed.add(new RunOutcome.Failure(i, Double.NaN, h.status().name().toLowerCase(Locale.ROOT),
                            t != null ? t + (where == null ? "" : " at " + where) : h.lastError()));
                }
            }
            boolean settled = r.state() != PacedRunner.State.RUNNING;
            RunFacts facts = settled ? RunFacts.live(session.engine()) : null;
            RunOutcome outcome = new RunOutcome(RunMessages.described(session), failed, facts);
            return RunPage.write(ReplayFiles.open(dir), outcome, "the window's run, up to " + String.format(Locale.ROOT,
                    "%.1f s", r.latest().timeSeconds()), out);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the run's trace " + trace + ": " + e.getMessage(), e);
        } finally {
            try (var files = Files.walk(dir)) {
                for (Path p : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(p);
                }
            } catch (IOException e) {
                // a temporary folder left behind
            }
        }
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
        shown = null;
        feed.back(player);
        if (arenaBefore != null) {
            model.restore(arenaBefore);
            choices.arenaFile = fileBefore;
            arenaBefore = null;
        }
        console.note("Replay closed."
                + (model.dirty() ? " The arena " + model.arena().name() + " is back as it was, with"
                + " its unsaved changes." : ""));
        fit.run();
    }
}
