/**
 * {@code khepera-link calibrate}: the guided procedure that measures one real robot over the serial
 * link (wheels, a white wall at distances and headings, a lamp) and writes its raw samples and a dated
 * calibration file the simulator loads (docs/calibration.md).
 */
package org.kheperasim.link.calibrate;
