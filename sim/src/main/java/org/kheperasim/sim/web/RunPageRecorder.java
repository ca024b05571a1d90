package org.kheperasim.sim.web;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.run.EditLog;

/**
 * Keeps what a run's web page needs while the run goes, for a run that writes no trace (or whose
 * trace is not at hand): attach it as a snapshot listener every {@link #PERIOD_MILLIS} ms, pass it
 * the run's console lines, and give it to {@link RunPage#write(RunPageRecorder, RunOutcome, java.nio.file.Path)}
 * at the end. Snapshots come on the engine's thread; the page may be written from any other.
 * About 100 bytes per robot per sample (5 MB for a 600 s run of 4 robots at 50 ms).
 */
public final class RunPageRecorder implements SnapshotListener {
    /** The period to attach it with, simulated ms: the trace's default sample period. */
    public static final long PERIOD_MILLIS = 50;

    private final Arena start;
    private final EditLog edits;
    private final RunTape tape;
    private final List<ConsoleLine> errors = new ArrayList<>();

    /**
     * @param start the arena as the run starts
     * @param edits the run's arena edits (stamped with their simulated times; may grow during the
     *     run, as the window's do), or null when the arena does not change
     */
    public RunPageRecorder(Arena start, EditLog edits) {
        this.start = start;
        this.edits = edits;
        this.tape = new RunTape(start);
    }

    @Override
    public synchronized void onSnapshot(Snapshot snapshot) {
        tape.add(snapshot, arenaAt(snapshot.timeNanos()));
    }

    /**
     * Keeps a controller's errors, whose times and texts mark its failure on the page's timeline.
     *
     * @param line a line of the run's console (messages and notes are ignored)
     */
    public synchronized void console(ConsoleLine line) {
        if (line.kind() == ConsoleLine.Kind.ERROR && errors.size() < 1000) {
            errors.add(line);
        }
    }

    synchronized RunTape tape() {
        return tape;
    }

    synchronized List<ConsoleLine> errors() {
        return List.copyOf(errors);
    }

    private Arena arenaAt(long nanos) {
        Arena a = start;
        if (edits != null) {
            for (EditLog.Edit e : edits.edits()) {
                if (e.timeNanos() <= nanos) {
                    a = e.arena();
                }
            }
        }
        return a;
    }
}
