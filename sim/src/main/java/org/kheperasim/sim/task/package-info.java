/**
 * Scoring a run against its arena's assignment ({@link org.kheperasim.sim.arena.Assignment}: the
 * {@code task} and {@code time-limit} lines of an arena file). {@link org.kheperasim.sim.task.RunFacts}
 * is what a run knows (regions entered, floor covered, caps per region), taken from a finished
 * run's result or from a live engine; {@link org.kheperasim.sim.task.Score#of} turns it into points.
 * No AWT: the window, {@code run} and {@code grade} all score through here.
 */
package org.kheperasim.sim.task;
