/**
 * The run's settings and what they make of each robot: {@link org.kheperasim.sim.engine.model.Settings} (every
 * named setting, the {@code wsu} profile), {@link org.kheperasim.sim.engine.model.RobotModel} (a robot type with the
 * settings applied: stepping, link, noise, sensors, motors, gripper), the vision turret's model, a robot's
 * miscalibration, and the tick ({@link org.kheperasim.sim.engine.model.Ticks}).
 */
package org.kheperasim.sim.engine.model;
