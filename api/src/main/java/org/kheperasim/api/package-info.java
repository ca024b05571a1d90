/**
 * The student-facing API of the Khepera simulator and its serial twin: everything a controller
 * may touch. The same classes work in the simulator and on the real robot, so a controller written
 * against this package runs unchanged on both.
 *
 * <h2>The controller contract</h2>
 * A controller is a subclass of {@link java.lang.Thread} with a public constructor
 * {@code (CurrentRobotState, MessagePasser)}, as in the WSU simulator paper's Appendix:
 * <pre>{@code
 * public class Robot extends Thread {
 *     public Robot(CurrentRobotState data, MessagePasser mp) { ... }
 *     public void killControl() { active = false; }   // optional: asked to stop
 *     public void run() { ... }                       // the controller's program
 * }
 * }</pre>
 * The backend constructs it, calls {@code start()}, and to stop it calls {@code killControl()} if
 * the class declares one (the simulator on the controller's own thread, when it next calls the API
 * or loops; robot-link on a thread of its own). A friendlier base class, {@link org.kheperasim.api.Controller}, offers
 * a {@code doWork()} loop, enums and helpers; it needs no constructor at all.
 *
 * <h2>Units and conventions (stated once, here)</h2>
 * <ul>
 *   <li><b>Sensor index order</b> (both proximity and light, as in the Khepera's {@code N} and
 *       {@code O} replies): 0 left 90°, 1 left 45°, 2 front left, 3 front right, 4 right 45°,
 *       5 right 90°, 6 back right, 7 back left. See {@link org.kheperasim.api.IrSensor}.</li>
 *   <li><b>Proximity</b>: 0..1023, <em>higher is nearer</em>. About 1000 touching a white wall,
 *       about 600 at 15–20 mm, a noise floor of a few tens beyond about 50 mm. Another robot reads on
 *       its own scale, 0..{@link org.kheperasim.api.Sensor#getMaxDistValue()} (an e-puck's 0..4095).</li>
 *   <li><b>Ambient light</b>: 0..1023 (10-bit), <em>lower is brighter</em>; about 450–500 in the
 *       dark, falling towards 20 next to a lamp.</li>
 *   <li><b>Wheel speed</b>: signed integer, −127..127; one unit is one encoder pulse per 10 ms,
 *       about 8 mm/s. Another robot's units and limit: {@link org.kheperasim.api.Motor#getMmPerSecondPerUnit()}
 *       and {@link org.kheperasim.api.Motor#getMaxSpeed()} (docs/robot-files.md).</li>
 *   <li><b>Wheel position</b> (encoders): signed 32-bit count of pulses, one pulse about 0.08 mm of
 *       wheel travel. They stop counting when the robot is blocked.</li>
 *   <li><b>Time</b>: {@code Thread.sleep(ms)} sleeps that many milliseconds of robot time. In the
 *       simulator robot time is simulated time; on the real robot it is wall time.</li>
 *   <li><b>Coordinates</b> (arena and robot poses, in the simulator): millimetres, x to the right,
 *       y up, origin at the arena's lower-left corner; headings in degrees, counter-clockwise,
 *       0 = facing +x. On the robot, x points forward and y to the left.</li>
 * </ul>
 */
package org.kheperasim.api;
