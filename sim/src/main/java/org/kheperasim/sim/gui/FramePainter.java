package org.kheperasim.sim.gui;

import java.util.Locale;
import javax.swing.Timer;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.run.PacedRunner;

/**
 * The window's frame clock: a Swing timer that, each frame, moves a replay on, feeds the plot and
 * the sensor panel when the shown world changed, repaints the arena, counts frames per second, and
 * updates the status bar. It only reads what the sources published: the engine never waits for it.
 */
final class FramePainter {
    /** Frame period while paced, ms: a little faster than 60 frames/s, so the screen keeps up. */
    private static final int FRAME_MS = 12;
    /** Frame period at full speed, ms: the engine and the controller want both cores then. */
    private static final int FRAME_MS_MAX_SPEED = 40;

    private final ViewFeed feed;
    private final ReplayPlayer player;
    private final ReplayBar replayBar;
    private final PlotPanel plot;
    private final javax.swing.JComponent sensorPanel;
    private final ArenaView arenaView;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunControls runs;
    private final RunChoices choices;
    private final Timer timer;
    private Snapshot lastPainted;
    private long fpsFrames;
    private long fpsSince = System.nanoTime();
    private double fps;

    FramePainter(ViewFeed feed, ReplayPlayer player, ReplayBar replayBar, PlotPanel plot,
            javax.swing.JComponent sensorPanel,
            ArenaView arenaView, ConsolePanel console, StatusBar status, RunControls runs, RunChoices choices) {
        this.feed = feed;
        this.player = player;
        this.replayBar = replayBar;
        this.plot = plot;
        this.sensorPanel = sensorPanel;
        this.arenaView = arenaView;
        this.console = console;
        this.status = status;
        this.runs = runs;
        this.choices = choices;
        timer = new Timer(FRAME_MS, e -> tick());
        timer.start();
    }

    /** The next frame redraws the panels even if the world did not change (another robot selected). */
    void forget() {
        lastPainted = null;
    }

    void stop() {
        timer.stop();
    }

    /** @return frames per second the arena view painted over the last second */
    double fps() {
        return fps;
    }

    private void tick() {
        console.drain();
        player.advance();
        replayBar.update();
        Snapshot s = feed.snapshot();
        if (s != lastPainted) {
            org.kheperasim.sim.engine.view.RobotView selected = feed.selected();
            plot.show(feed.selectedSeries(), selected == null ? null : selected.type(), s == null ? 0 : s.timeSeconds(),
                    player.open() ? player.cursor() : Double.NaN);
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
        PacedRunner r = runs.runner();
        String rtf = player.open() ? String.format(Locale.ROOT, "%.2fx", player.playing() ? player.speed() : 0.0)
                : r == null || r.state() != PacedRunner.State.RUNNING ? "-"
                : String.format(Locale.ROOT, "%.2fx", r.realTimeFactor());
        timer.setDelay(choices.speed == PacedRunner.MAX_SPEED && !player.open() ? FRAME_MS_MAX_SPEED : FRAME_MS);
        status.update(feed.state(), s == null ? 0.0 : s.timeSeconds(), rtf, fps, arenaView.mouse());
        status.score(feed.source() == runs ? runs.score() : null);
    }
}
