/**
 * World (map) files of the original WSU Khepera Simulator: {@link org.kheperasim.sim.arena.wsu.WsuWorld}
 * reads one into an {@link org.kheperasim.sim.arena.Arena} without deserialising anything. The
 * layers: {@code StreamInput} (bytes), {@code SerialStreamParser} (the serialization stream
 * grammar), {@code WsuWorldObjects} (the Vector of Vertex objects), {@code WsuArenaBuilder} (pixels
 * to millimetres, footprints, the border, clipping) and {@code RobotPlacement} (a free start).
 * {@link org.kheperasim.sim.arena.wsu.WsuWorldImport} offers the reader to the arena files as their
 * {@link org.kheperasim.sim.arena.WsuWorldReader} service.
 */
package org.kheperasim.sim.arena.wsu;
