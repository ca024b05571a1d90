/**
 * The arena as the engine holds it: the {@link org.kheperasim.sim.engine.space.World} (walls drawn into the grid,
 * lamps, caps), the robots' bodies as discs ({@code Bodies}, {@code RobotsInReach}), the caps on the floor
 * ({@code Caps}) and the geometry that bounds a glide ({@code ArcTrig}, {@code ClearanceProof}).
 */
package org.kheperasim.sim.engine.space;
