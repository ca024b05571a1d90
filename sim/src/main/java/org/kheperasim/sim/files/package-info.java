/**
 * Files a person reads and writes: one atomic save ({@link org.kheperasim.sim.files.AtomicFiles}) for
 * every file the simulator saves, bounded strict UTF-8 reading that looks at a file before it opens it (a pipe or a
 * device is refused; {@link org.kheperasim.sim.files.TextFiles}), bounded lines of a stream read as it comes
 * ({@link org.kheperasim.sim.files.BoundedLines}),
 * and the common type of the readers' errors ({@link org.kheperasim.sim.files.InputFileException}), which
 * always name the file and the line at fault.
 */
package org.kheperasim.sim.files;
