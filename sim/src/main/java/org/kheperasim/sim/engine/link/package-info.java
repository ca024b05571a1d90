/**
 * The simulated serial line between a controller and its robot: commands in flight with their wire times ({@code
 * RobotLink}, {@code CommandQueue}) and the robot's end, which applies them to its parts and fills poll replies
 * ({@code LinkEnd}).
 */
package org.kheperasim.sim.engine.link;
