/**
 * What a robot senses: its infrared proximity and ambient light sensors placed by its robot type ({@code
 * SensorPlacement}), scanned on the poll cycle ({@code Scans}, {@code SamplePose}), the linear vision turret, and
 * what it has visited ({@code Coverage}: floor cells and the regions entered).
 */
package org.kheperasim.sim.engine.sensing;
