/**
 * A real robot's calibration in the simulator: the overlay file {@code khepera-link calibrate}
 * writes, loaded onto its base robot type (docs/calibration.md).
 */
package org.kheperasim.sim.calibration;
