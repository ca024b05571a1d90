/**
 * The arena: what the robots live in, as a model, as a file, and as the grid the engine senses
 * and collides against. No AWT or Swing here; everything is deterministic.
 *
 * <p>Conventions: millimetres; x to the right, y up, origin at the arena's lower-left corner;
 * headings in degrees counter-clockwise, 0 = facing +x.
 *
 * <ul>
 *   <li>{@link org.kheperasim.sim.arena.Arena} and its parts ({@link org.kheperasim.sim.arena.Pose},
 *       {@link org.kheperasim.sim.arena.Wall}, {@link org.kheperasim.sim.arena.Light},
 *       {@link org.kheperasim.sim.arena.Cap}, {@link org.kheperasim.sim.arena.Region}): the
 *       immutable model.</li>
 *   <li>{@link org.kheperasim.sim.arena.ArenaFormat}: the hand-written {@code .arena} text files
 *       (see {@code docs/arena-format.md}), the bundled arenas, atomic saving and content
 *       hashes.</li>
 *   <li>{@link org.kheperasim.sim.arena.OccupancyGrid}: the paper's 500 x 500 environment matrix
 *       of cell ids, with ray casting and line-of-sight tests.</li>
 *   <li>{@link org.kheperasim.sim.arena.DistanceField}: clearance from every point to the nearest
 *       obstacle, for collisions.</li>
 *   <li>{@link org.kheperasim.sim.arena.ShapeIndex}: the walls and lamps as their exact shapes
 *       (capsules, discs) in buckets, which the proximity beams are cast against.</li>
 *   <li>{@link org.kheperasim.sim.arena.ArenaFiles}: a file of either format becomes an arena; WSU
 *       world files are read through {@link org.kheperasim.sim.arena.WsuWorldReader}, implemented
 *       by the importer in {@code arena.wsu}, which builds on this package (never the other way).</li>
 * </ul>
 */
package org.kheperasim.sim.arena;
