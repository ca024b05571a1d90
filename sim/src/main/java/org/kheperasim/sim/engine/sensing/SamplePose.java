package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.engine.body.DriveBody;

/**
 * Where a robot is for the poll sample being taken, a number of ticks into its present move: its
 * position, heading and wheel counters, each computed only when a sample asks for it (a sample in
 * the open needs no heading, a light sample in the dark nothing, a counter sample no trigonometry).
 */
public final class SamplePose {
    private final DriveBody body;
    /** x, y, cos, sin, left and right encoder, as far as known. */
    private final double[] pose = new double[6];
    private long ticks;
    private boolean position;
    private boolean heading;
    private boolean counters;

    public SamplePose(DriveBody body) {
        this.body = body;
    }

    /** Samples from now on are taken {@code ticks} ticks into the present move (before it is made). */
    public void at(long ticks) {
        this.ticks = ticks;
        position = false;
        heading = false;
        counters = false;
    }

    /** @return {x, y, -, -, left, right}: the position and counters */
    double[] position() {
        if (!position) {
            body.preview().position(ticks, pose);
            position = true;
            counters = true;
        }
        return pose;
    }

    /** @return {x, y, cos, sin, left, right} */
    double[] pose() {
        position();
        if (!heading) {
            body.preview().heading(ticks, pose);
            heading = true;
        }
        return pose;
    }

    /** @return {-, -, -, -, left, right}: the counters, in pulses of travel */
    public double[] counters() {
        if (!counters) {
            body.preview().counters(ticks, pose);
            counters = true;
        }
        return pose;
    }
}
