package org.kheperasim.sim.gui;

import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.RobotSeries;

/**
 * Plays a {@link Replay} in the window like a recorder: a cursor on the run's timeline that plays
 * at a chosen speed, pauses, steps sample by sample, rewinds and jumps. The arena drawn follows the
 * run's stamped edits. Event thread only; {@link #advance} is called once per frame.
 */
final class ReplayPlayer implements SnapshotSource {
    /** Playback speeds offered, simulated seconds per real second. */
    static final double[] SPEEDS = {0.25, 0.5, 1, 2, 4, 8, 16, 64};

    private final EditorModel model;
    private Replay replay;
    private double cursor;
    private boolean playing;
    private double speed = 1;
    private long lastNanos;
    private Snapshot cached;
    private double cachedAt = Double.NaN;
    private Arena shownArena;

    ReplayPlayer(EditorModel model) {
        this.model = model;
    }

    /** @param r the run to play, from its start, paused */
    void load(Replay r) {
        replay = r;
        playing = false;
        cachedAt = Double.NaN;
        shownArena = null;
        seek(r.startSeconds());
    }

    /** Forget the replay. */
    void unload() {
        replay = null;
        playing = false;
        cached = null;
        cachedAt = Double.NaN;
    }

    /** @return the replay, or null */
    Replay replay() {
        return replay;
    }

    /** @return true while a replay is open */
    boolean open() {
        return replay != null;
    }

    @Override
    public Snapshot snapshot() {
        if (replay == null) {
            return null;
        }
        if (cursor != cachedAt) {
            cached = replay.at(cursor);
            cachedAt = cursor;
        }
        return cached;
    }

    @Override
    public String state() {
        return replay == null ? null : playing ? "replay, playing" : "replay, paused";
    }

    @Override
    public float[] trail(int robot) {
        return replay == null || robot >= replay.robotCount() ? new float[0] : replay.trail(robot, cursor);
    }

    @Override
    public RobotSeries series(int robot) {
        return replay == null || robot >= replay.robotCount() ? null : replay.series(robot);
    }

    /** @return the cursor, s */
    double cursor() {
        return cursor;
    }

    /** @return true while playing */
    boolean playing() {
        return playing;
    }

    /** @return the playback speed */
    double speed() {
        return speed;
    }

    /** @param s simulated seconds per real second */
    void setSpeed(double s) {
        speed = s;
    }

    /** @param t move the cursor there (clamped to the run) */
    void seek(double t) {
        if (replay == null) {
            return;
        }
        cursor = StrictMath.max(replay.startSeconds(), StrictMath.min(replay.endSeconds(), t));
        Arena a = replay.arenaAt(cursor);
        if (a != shownArena) {
            shownArena = a;
            model.load(a);
        }
    }

    void play() {
        if (replay == null) {
            return;
        }
        if (cursor >= replay.endSeconds()) {
            seek(replay.startSeconds());
        }
        playing = true;
        lastNanos = System.nanoTime();
    }

    void pause() {
        playing = false;
    }

    void toggle() {
        if (playing) {
            pause();
        } else {
            play();
        }
    }

    void rewind() {
        seek(replay == null ? 0 : replay.startSeconds());
    }

    /** Fast-forward: play at the next faster speed. */
    void fastForward() {
        for (double s : SPEEDS) {
            if (s > speed) {
                speed = s;
                break;
            }
        }
        play();
    }

    /** @param samples how many samples to move (negative: back); pauses */
    void step(int samples) {
        if (replay == null) {
            return;
        }
        pause();
        RobotSeries s = replay.series(0);
        int k = StrictMath.max(0, StrictMath.min(s.size() - 1, s.indexAt(cursor) + samples));
        seek(s.time(k));
    }

    /** Move the cursor by the real time passed since the last frame, times the speed. */
    void advance() {
        long now = System.nanoTime();
        if (playing && replay != null) {
            seek(cursor + (now - lastNanos) / 1e9 * speed);
            if (cursor >= replay.endSeconds()) {
                playing = false;
            }
        }
        lastNanos = now;
    }
}
