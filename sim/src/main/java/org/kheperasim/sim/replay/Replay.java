package org.kheperasim.sim.replay;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.run.EditLog;

/**
 * A whole run read back for watching: the arena (and its stamped edits), every robot's samples and
 * every cap's moves, as a {@link Snapshot} at any time between {@link #startSeconds()} and
 * {@link #endSeconds()}. Made by {@link ReplayFiles}.
 */
public final class Replay {
    /** What the replay was read from. */
    public enum Kind {
        /** a run recording folder (start arena, edits, settings, trace) */
        RECORDING,
        /** a trace file */
        TRACE,
        /** a robot-link recording of a real robot (pose from its encoders) */
        LINK_RECORDING
    }

    private final Kind kind;
    private final String source;
    private final Arena arena;
    private final List<EditLog.Edit> edits;
    private final List<RobotSeries> robots;
    private final CapTrack caps;
    private final List<String> notes;

    Replay(Kind kind, String source, Arena arena, List<EditLog.Edit> edits, List<RobotSeries> robots, CapTrack caps,
            List<String> notes) {
        if (robots.isEmpty() || robots.get(0).size() == 0) {
            throw new IllegalArgumentException(source + ": there is no sample to replay");
        }
        this.kind = kind;
        this.source = source;
        this.arena = arena;
        this.edits = List.copyOf(edits);
        this.robots = List.copyOf(robots);
        this.caps = caps;
        this.notes = List.copyOf(notes);
    }

    /** @return what it was read from */
    public Kind kind() {
        return kind;
    }

    /** @return the file or folder, as the user named it */
    public String source() {
        return source;
    }

    /** @return the arena at the start */
    public Arena arena() {
        return arena;
    }

    /** @return what the reader has to say (a file cut short, an arena found by name), for the console */
    public List<String> notes() {
        return notes;
    }

    /** @return robots replayed */
    public int robotCount() {
        return robots.size();
    }

    /** @param robot index @return its samples */
    public RobotSeries series(int robot) {
        return robots.get(robot);
    }

    /** @return the first sample's time, s */
    public double startSeconds() {
        return robots.get(0).time(0);
    }

    /** @return the last sample's time, s */
    public double endSeconds() {
        double end = 0;
        for (RobotSeries r : robots) {
            end = StrictMath.max(end, r.lastTime());
        }
        return end;
    }

    /** @return the samples of robot 0 (for stepping from sample to sample) */
    public int samples() {
        return robots.get(0).size();
    }

    /** @param t s @return the world as recorded at the last sample at or before {@code t} */
    public Snapshot at(double t) {
        List<RobotView> views = new ArrayList<>(robots.size());
        double shown = 0;
        for (int i = 0; i < robots.size(); i++) {
            RobotSeries s = robots.get(i);
            int k = StrictMath.max(0, s.indexAt(t));
            shown = StrictMath.max(shown, s.time(k));
            views.add(s.view(i, "robot" + i, k, "replay"));
        }
        return new Snapshot(StrictMath.round(shown * 1e9), views, caps == null ? List.of() : caps.at(t));
    }

    /** @param t s @return the arena as edited up to {@code t} */
    public Arena arenaAt(double t) {
        Arena a = arena;
        for (EditLog.Edit e : edits) {
            if (e.timeNanos() <= StrictMath.round(t * 1e9)) {
                a = e.arena();
            }
        }
        return a;
    }

    /** @return true when the arena changes during the run */
    public boolean hasEdits() {
        return !edits.isEmpty();
    }

    /** @param robot index @param t s @return its path up to {@code t}, x0, y0, x1, y1, … mm */
    public float[] trail(int robot, double t) {
        RobotSeries s = robots.get(robot);
        return s.trail(s.indexAt(t));
    }
}
