/**
 * The real robot behind the student API: {@link org.kheperasim.link.robot.RobotBackend} keeps the
 * {@code api} objects fresh with a poll loop and sends motor and gripper commands when they change;
 * {@link org.kheperasim.link.robot.RobotRun} runs a controller on it and stops the robot
 * ({@code D,0,0}) on every way out; {@link org.kheperasim.link.robot.ControllerLoader} finds
 * controller classes by the names the simulator uses.
 */
package org.kheperasim.link.robot;
