/**
 * {@code khepera-sim compare}: a real run recorded by robot-link replayed with the same controller
 * from the same start in the simulator, and where the two diverge (docs/calibration.md).
 */
package org.kheperasim.sim.compare;
