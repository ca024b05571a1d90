package org.kheperasim.sim.gui;

import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * The window's score of a live run, the one {@code run} prints: the start arena's assignment scored
 * on the engine's own facts (the floor its robots' bodies covered, the regions entered to the
 * millisecond, the caps in each region), read on the engine's thread when the runner publishes a
 * snapshot. Counting the floor walks the covered cells, so while the run goes on it is scored at
 * most every {@link #EVERY_WALL_NANOS} of real time; whenever the run settles (paused, stepped,
 * ended) it is scored at once, so a paused or ended run shows exactly its score at that moment.
 */
final class LiveScore implements PacedRunner.PublishListener {
    /** Real time between two scorings of a running run, ns: faster than the eye reads the status bar. */
    private static final long EVERY_WALL_NANOS = 50_000_000L;

    private final Arena arena;
    private volatile Score score;
    private long lastWall = Long.MIN_VALUE;

    /** @param arena the run's start arena, whose assignment {@code run} scores */
    LiveScore(Arena arena) {
        this.arena = arena;
    }

    @Override
    public void published(RunSession session, boolean settled) {
        long now = System.nanoTime();
        if (settled || score == null || now - lastWall >= EVERY_WALL_NANOS) {
            score = Score.of(arena, RunFacts.live(session.engine()));
            lastWall = now;
        }
    }

    /** @return the score at the last snapshot scored, or null before the first */
    Score score() {
        return score;
    }

    /** @return e.g. {@code score 39.77/100 (cover 50: 19.9% of 50% of the floor)}, or null before the first */
    String text() {
        Score s = score;
        return s == null ? null : "score " + s.summary();
    }
}
