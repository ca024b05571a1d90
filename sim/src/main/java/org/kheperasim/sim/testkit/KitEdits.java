package org.kheperasim.sim.testkit;

import java.nio.file.Path;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.run.EditLog;

/** A window's arena edits with their times ({@code run.edits} of a run recording). */
public final class KitEdits {
    final EditLog log;

    KitEdits(EditLog log) {
        this.log = log;
    }

    /** @param file a {@code run.edits} file @return its edits */
    public static KitEdits load(Path file) {
        return new KitEdits(EditLog.load(file));
    }

    /**
     * @param start the arena the run started in
     * @param nanos simulated time, ns
     * @return the arena as it was then
     */
    public KitArena arenaAt(KitArena start, long nanos) {
        Arena a = start.arena;
        for (EditLog.Edit e : log.edits()) {
            if (e.timeNanos() <= nanos) {
                a = e.arena();
            }
        }
        return a == start.arena ? start : new KitArena(a);
    }
}
