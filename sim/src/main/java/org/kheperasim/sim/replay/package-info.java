/**
 * What a run did, sample by sample, for watching and plotting it: {@link org.kheperasim.sim.replay.RobotSeries}
 * (one robot's sensors, wheels, encoders and pose over time, filled live by
 * {@link org.kheperasim.sim.replay.SeriesRecorder} or read from a file), and
 * {@link org.kheperasim.sim.replay.Replay} (a whole run read back from a run recording, a trace or a
 * robot-link recording of a real robot, as snapshots at any time). Free of AWT and Swing.
 */
package org.kheperasim.sim.replay;
