package org.kheperasim.sim.gui;

import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.replay.RobotSeries;

/**
 * What the window shows: a live run, a served arena or a replay. The arena view, the sensor panel
 * (with the gripper icons), the plot and the status bar read only this, so they work the same for
 * all three. Read on the event thread.
 */
interface SnapshotSource {
    /** @return the world to draw now, or null when there is nothing (no run yet) */
    Snapshot snapshot();

    /** @return the state in words for the panels (running, paused, serving, replay, …), or null with nothing to show */
    String state();

    /** @param robot a robot's index @return its path so far, x0, y0, x1, y1, … mm */
    float[] trail(int robot);

    /** @param robot a robot's index @return its samples so far for the plot, or null when none are kept */
    RobotSeries series(int robot);
}
