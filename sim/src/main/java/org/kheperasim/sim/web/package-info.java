/**
 * A run as one self-contained web page that replays it in any browser
 * ({@link org.kheperasim.sim.web.RunPage}): made from a trace or a run recording, or from a run
 * recorded as it goes ({@link org.kheperasim.sim.web.RunPageRecorder}), with what the run's result
 * adds ({@link org.kheperasim.sim.web.RunOutcome}). The page's drawing follows the window's; its
 * script and style are resources beside these classes. Free of AWT and Swing.
 */
package org.kheperasim.sim.web;
