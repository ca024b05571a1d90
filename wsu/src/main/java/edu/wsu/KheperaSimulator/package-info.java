/**
 * The controller API of the original WSU Khepera Simulator (2001–2007), so that controllers
 * written for it compile against {@code khepera-sim.jar} and run unchanged, in the simulator and on
 * a real Khepera through robot-link. Written anew from the documented interface; the names, types
 * and constants are the original's, so classes compiled against the original link here too.
 *
 * <ul>
 *   <li>{@link edu.wsu.KheperaSimulator.RobotController}: the base class; a controller implements
 *       {@code doWork()} and {@code close()} and has a public constructor without parameters.</li>
 *   <li>{@link edu.wsu.KheperaSimulator.KSGripperStates}: the arm and finger states 20..23.</li>
 *   <li>{@link edu.wsu.KheperaSimulator.CurrentRobotState}: the robot behind a controller.</li>
 * </ul>
 *
 * <h2>Units</h2>
 * <ul>
 *   <li><b>Speed</b>: −9..9 per wheel; one unit is one Khepera speed unit (one encoder pulse per
 *       10 ms, ≈ 8 mm/s), the mapping the original's remote-robot program used on the real robot. A
 *       value outside −9..9 is ignored and that wheel keeps its speed.</li>
 *   <li><b>Wheel positions</b>: {@code long} counts of encoder pulses (≈ 0.08 mm each), 0 at the
 *       start of each run.</li>
 *   <li><b>Proximity</b>: 0..1023, higher = nearer. <b>Ambient light</b>: 0..1023, lower =
 *       brighter. Sensor order: 0 left, 1 left 45°, 2 front left, 3 front right, 4 right 45°,
 *       5 right, 6 rear right, 7 rear left.</li>
 *   <li><b>Time</b>: milliseconds of robot time: simulated time in the simulator, wall time on
 *       the robot.</li>
 * </ul>
 */
package edu.wsu.KheperaSimulator;
