/**
 * The engine: the world stepped tick by tick in lockstep with its drivers (the controllers). This package is the
 * top of the engine and the only one that knows every part: {@link org.kheperasim.sim.engine.Engine} (the tick
 * loop, the drivers, the listeners), {@link org.kheperasim.sim.engine.SimRobot} (one robot assembled from its
 * parts), the motion of all robots together ({@code Motion}, {@code Crowd}, {@code Glides}, {@code SplitWork}) and the
 * ends of a controller's link ({@code ControllerLink}, {@code OnBoardControl}, {@code OnBoardLink}).
 *
 * <p>Below it, each sub-package depends only on those under it, never back up (checked by
 * {@code NoPackageCyclesTest}): {@code link} (the simulated serial line), {@code sensing} (proximity, light, vision,
 * coverage), {@code body} (wheels, contacts, the gripper), {@code space} (the arena as the engine holds it),
 * {@code view} (what the engine shows: snapshots, views, the drivers' log), {@code model} (the settings and what
 * they make of each robot, the tick), {@code robot} (the robot as data, its files) and {@code noise}.
 */
package org.kheperasim.sim.engine;
