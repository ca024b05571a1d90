/**
 * The operating-system box around code that is not the user's own: a JVM started by bubblewrap in
 * an empty file tree that holds only the Java runtime, the simulator and the files of one run, with no
 * network, its own process namespace, no capabilities, and limits on processes, files, memory and CPU
 * time that hold even for a grader running as root ({@link org.kheperasim.sim.sandbox.Box}). Used by
 * {@code grade} for every run and by {@code run --sandbox} and {@code serve --sandbox}
 * ({@link org.kheperasim.sim.sandbox.Reexec}). Documented in {@code docs/grading.md}, "The sandbox".
 */
package org.kheperasim.sim.sandbox;
