/**
 * A run's command log and its open-loop replay. While a run goes, the engine tells a
 * {@link org.kheperasim.sim.engine.view.DriverRecorder} everything its controllers do to the world (the
 * commands that reach each robot's link, emergency stops, when each controller wakes, the reads that
 * bring a reply in early, each image the vision turret takes, where a run stopped early ends);
 * {@link org.kheperasim.sim.commandlog.CommandLogWriter} writes it as text,
 * {@link org.kheperasim.sim.commandlog.LogChannel} hands it from a graded child JVM to its grader,
 * and {@link org.kheperasim.sim.commandlog.OpenLoopReplay} makes the same run again from it with no
 * controller code, byte for byte in its trace, so that the grader scores what the robot did and never
 * what the run says it scored. Documented in {@code docs/grading.md}, "The score is the grader's".
 */
package org.kheperasim.sim.commandlog;
