package org.kheperasim.testing;

/**
 * One task of the arena's assignment (a {@code task} line of its file) and what the run earned for it.
 *
 * @param task the task line as written in the arena file, e.g. {@code task reach goal points 60}
 * @param fraction how much of it was done, 0..1
 * @param points points earned: {@code fraction} times the task's points
 * @param max the task's points
 * @param detail what was counted, e.g. {@code 17/25 regions} or {@code reached at 41.3 s}
 */
public record TaskScore(String task, double fraction, double points, double max, String detail) {
}
