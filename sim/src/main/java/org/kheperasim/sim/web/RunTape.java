package org.kheperasim.sim.web;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.replay.Replay;

/**
 * A run as the page replays it, filled from snapshots in time order (a live run's, or a replay's
 * at each of its sample times): every robot's samples (time, pose, wheels, encoders, contact,
 * gripper; the 16 sensor values for the first {@link #SENSOR_ROBOTS}), every cap's moves, the arena
 * as edited, and when a robot's controller was first seen failed. Values are kept as the page
 * shows them: times in ms, lengths in 0.1 mm, angles in 0.1 degree.
 */
final class RunTape {
    /** Robots whose sensor values are kept (as the window's plots keep {@code SeriesRecorder.MAX_ROBOTS}). */
    static final int SENSOR_ROBOTS = 16;
    /** Robots kept at all: a larger swarm's page shows these. */
    static final int MAX_ROBOTS = 64;

    /** The arena from {@code ms} on. */
    record ArenaVersion(long ms, Arena arena) {
    }

    /** One cap's move: where it lay, or who held it, from {@code ms} on. */
    record CapMove(long ms, int cap, int x10, int y10, int heldBy, double radius) {
    }

    /** One robot's samples, column by column. */
    static final class Track {
        final String name;
        final IntList t = new IntList();
        final IntList x = new IntList();
        final IntList y = new IntList();
        final IntList h = new IntList();
        final IntList speedL = new IntList();
        final IntList speedR = new IntList();
        final IntList encL = new IntList();
        final IntList encR = new IntList();
        final IntList contact = new IntList();
        final IntList arm = new IntList();
        final IntList fingers = new IntList();
        final IntList object = new IntList();
        final IntList held = new IntList();
        /** 8 proximity then 8 light columns, or null when not kept. */
        final IntList[] sensors;
        /** When the controller was first seen failed, ms, or -1; and how. */
        long failedMs = -1;
        String failedStatus;

        /** The robot's type: what the page draws. */
        org.kheperasim.sim.engine.robot.RobotType type = org.kheperasim.sim.engine.robot.RobotTypes.KHEPERA1;

        Track(String name, boolean keepSensors) {
            this.name = name;
            sensors = keepSensors ? new IntList[16] : null;
            if (keepSensors) {
                for (int i = 0; i < 16; i++) {
                    sensors[i] = new IntList();
                }
            }
        }

        /** @return every column but the sensors, in the page's order */
        IntList[] columns() {
            return new IntList[] {t, x, y, h, speedL, speedR, encL, encR, contact, arm, fingers, object, held};
        }

        int size() {
            return t.size();
        }

        void add(long ms, RobotView r) {
            t.add((int) ms);
            x.add(tenths(r.x()));
            y.add(tenths(r.y()));
            h.add(tenths(r.headingDeg()));
            speedL.add(r.speedLeft());
            speedR.add(r.speedRight());
            encL.add(r.encoderLeft());
            encR.add(r.encoderRight());
            contact.add(r.contact().ordinal());
            GripperView g = r.gripper();
            arm.add(g.armPosition());
            fingers.add(g.fingers().ordinal());
            object.add(g.objectPresent() ? 1 : 0);
            held.add(g.heldCap() + 1);
            if (sensors != null) {
                // Eight columns whatever the robot, as in a trace: 0 for a sensor it does not have.
                int n = r.sensorCount();
                for (int i = 0; i < 8; i++) {
                    sensors[i].add(i < n ? r.proximity(i) : 0);
                    sensors[8 + i].add(i < n ? r.light(i) : 0);
                }
            }
            if (failedMs < 0 && r.controller() != null) {
                ControllerStatus s = status(r.controller());
                if (s != null && s.failed()) {
                    failedMs = ms;
                    failedStatus = s.name().toLowerCase(Locale.ROOT);
                }
            }
        }
    }

    private final List<Track> robots = new ArrayList<>();
    private final List<ArenaVersion> arenas = new ArrayList<>();
    private final List<CapMove> caps = new ArrayList<>();
    private final List<int[]> capLast = new ArrayList<>();
    private int robotsInRun;
    private long endMs = -1;

    /** @param start the arena as the run started */
    RunTape(Arena start) {
        arenas.add(new ArenaVersion(0, start));
    }

    /**
     * The run a replay holds, at each of its first robot's sample times.
     *
     * @param replay a trace, recording or robot-link recording read back
     * @return its tape
     */
    static RunTape of(Replay replay) {
        RunTape tape = new RunTape(replay.arena());
        int n = replay.samples();
        for (int k = 0; k < n; k++) {
            double t = replay.series(0).time(k);
            tape.add(replay.at(t), replay.arenaAt(t));
        }
        return tape;
    }

    /**
     * @param s the world at one instant, not before the last one added
     * @param arena the arena at that instant (as edited so far)
     */
    void add(Snapshot s, Arena arena) {
        long ms = StrictMath.round(s.timeNanos() / 1e6);
        if (ms < endMs) {
            return;
        }
        endMs = ms;
        if (arenas.get(arenas.size() - 1).arena() != arena) {
            arenas.add(new ArenaVersion(ms, arena));
        }
        List<RobotView> views = s.robots();
        robotsInRun = StrictMath.max(robotsInRun, views.size());
        for (int i = 0; i < StrictMath.min(views.size(), MAX_ROBOTS); i++) {
            if (i == robots.size()) {
                robots.add(new Track(views.get(i).name(), i < SENSOR_ROBOTS));
                robots.get(i).type = views.get(i).type();
            }
            robots.get(i).add(ms, views.get(i));
        }
        for (CapView c : s.caps()) {
            while (capLast.size() <= c.id()) {
                capLast.add(null);
            }
            int[] now = {tenths(c.x()), tenths(c.y()), c.heldBy()};
            int[] was = capLast.get(c.id());
            if (was == null || was[0] != now[0] || was[1] != now[1] || was[2] != now[2]) {
                capLast.set(c.id(), now);
                caps.add(new CapMove(ms, c.id(), now[0], now[1], now[2], c.radius()));
            }
        }
    }

    /** @return the robots kept, in engine order */
    List<Track> robots() {
        return robots;
    }

    /** @return how many robots the run had (more than {@link #robots()} for a large swarm) */
    int robotsInRun() {
        return robotsInRun;
    }

    /** @return the arena's versions, oldest first; the first from 0 ms */
    List<ArenaVersion> arenas() {
        return arenas;
    }

    /** @param ms a time @return the arena then */
    Arena arenaAt(long ms) {
        Arena a = arenas.get(0).arena();
        for (ArenaVersion v : arenas) {
            if (v.ms() <= ms) {
                a = v.arena();
            }
        }
        return a;
    }

    /** @return every cap move, in time order (a cap's first line where the run first saw it) */
    List<CapMove> caps() {
        return caps;
    }

    /** @return the last sample's time, ms (-1 before the first) */
    long endMs() {
        return endMs;
    }

    static int tenths(double v) {
        return (int) StrictMath.round(v * 10);
    }

    /** Each state by its word in either case; {@code valueOf} threw for every other word, every sample. */
    private static final Map<String, ControllerStatus> STATUS_WORDS = new HashMap<>();

    static {
        for (ControllerStatus s : ControllerStatus.values()) {
            STATUS_WORDS.put(s.name(), s);
            STATUS_WORDS.put(s.name().toLowerCase(Locale.ROOT), s);
        }
    }

    private static ControllerStatus status(String word) {
        ControllerStatus s = STATUS_WORDS.get(word);
        // "replay", "served" and the like are not a controller's state: null
        return s != null ? s : STATUS_WORDS.get(word.toUpperCase(Locale.ROOT));
    }
}
