package org.kheperasim.sim.engine.event;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;

/**
 * Publishes an engine's contacts and region entries as {@link EngineEvent}s.
 *
 * <p>It watches the end of every robot's move through {@link Engine#watchMoves}, and only reads: the
 * physics, the trace and the run are the same with or without it (an engine nobody watches pays one null
 * check per move). Each move is one tick with contact handling or a glide along which nothing can be
 * touched and no region not yet entered can be entered, so contacts and each region's first entry come
 * at their exact tick. Events of one stretch of moves are handed to the listener when the stretch ends,
 * on the turn holder's thread, sorted by time, then robot (the same order however many threads moved
 * the robots).
 *
 * <p>What it cannot do exactly: a robot that leaves a region it has already entered, or enters it
 * again, may do so inside a glide (the engine does not stop at regions already entered); the event then
 * has the glide's end, the robot's next stop (at most the next snapshot, command or wake-up). Robots added
 * to the engine after the watch began are not watched.
 */
public final class EngineEvents {
    private static final Comparator<EngineEvent> ORDER =
            Comparator.comparingLong(EngineEvent::timeNanos).thenComparingInt(EngineEvent::robot);

    private final EngineEventListener listener;
    private final RobotWatch[] watches;
    private final List<EngineEvent> batch = new ArrayList<>();

    private EngineEvents(Engine engine, EngineEventListener listener) {
        this.listener = listener;
        List<SimRobot> robots = engine.robots();
        Touches touches = new Touches(engine.world(), robots);
        this.watches = new RobotWatch[robots.size()];
        for (int i = 0; i < watches.length; i++) {
            watches[i] = new RobotWatch(robots.get(i), engine.world(), touches, engine.timeNanos());
        }
    }

    /**
     * Watch an engine from now on (an engine has one watch: a second replaces the first). What is true
     * already when the watch begins (a robot starting inside a region) is told at the watch's time.
     *
     * @param engine the engine, with its robots added
     * @param listener hears the events
     * @return the watch
     */
    public static EngineEvents watch(Engine engine, EngineEventListener listener) {
        EngineEvents e = new EngineEvents(engine, Objects.requireNonNull(listener));
        engine.watchMoves(e::moved, e::stretchEnded);
        return e;
    }

    private void moved(SimRobot robot, long endNanos) {
        if (robot.id() < watches.length) {
            watches[robot.id()].moved(endNanos);
        }
    }

    private void stretchEnded(long endNanos) {
        for (RobotWatch w : watches) {
            batch.addAll(w.pending);
            w.pending.clear();
        }
        if (batch.isEmpty()) {
            return;
        }
        batch.sort(ORDER);
        try {
            for (EngineEvent e : batch) {
                listener.onEvent(e);
            }
        } finally {
            batch.clear();
        }
    }
}
