/**
 * Grading a class: every submission (one folder per student, {@code .java} or {@code .class}) is
 * compiled, then run in every arena with every seed, each submission's runs one after another on a warm
 * worker JVM of its own ({@link org.kheperasim.sim.grade.WorkerSlots}, {@code grade.worker}; with
 * {@code --worker-runs 1} each run in a child JVM of its own, {@link org.kheperasim.sim.grade.ChildRun}),
 * each run with fresh class loaders, a heap limit, a simulated-time limit and a wall-clock limit, under
 * the containment rules and inside the operating-system sandbox ({@code sim.sandbox}); each run hands over its command
 * log, which the grader replays and scores by the arena's assignment ({@link org.kheperasim.sim.task.Score}), the
 * run's own result only compared with it ({@link org.kheperasim.sim.grade.Verdict}); each finished run
 * goes to a journal ({@link org.kheperasim.sim.grade.Journal}), so a grading goes on where it stopped.
 * The runs are reported as a table, CSV, JSON and an HTML page with a picture of each run's trajectory. A grading can
 * be cut into deterministic
 * shards ({@link org.kheperasim.sim.grade.GradePlan#shard}) that {@link org.kheperasim.sim.grade.ReportFiles}
 * merges into the same report. A grading may keep a deadline of its own
 * ({@link org.kheperasim.sim.grade.GradeDeadline}),
 * and {@code grade.platform} writes its results in the learning platforms' formats. Documented in
 * {@code docs/grading.md}.
 */
package org.kheperasim.sim.grade;
