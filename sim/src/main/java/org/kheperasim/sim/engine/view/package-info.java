/**
 * What the engine shows to the world outside it, as values: a {@link org.kheperasim.sim.engine.view.Snapshot} of the
 * world for listeners (robots, caps, vision images, contacts), and the {@link
 * org.kheperasim.sim.engine.view.DriverRecorder} that hears what the drivers do, for the command log and its replay.
 */
package org.kheperasim.sim.engine.view;
