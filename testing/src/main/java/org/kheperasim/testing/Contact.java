package org.kheperasim.testing;

import java.util.Locale;

/**
 * A time a robot's body touched something: from the first sample that saw it touching to the last.
 *
 * <p>The robot's contact is seen at the run's samples (every 50 ms unless {@link RunBuilder#sampleEvery}
 * says otherwise). A bump that begins and ends between two samples is still counted: the simulator counts
 * every move an obstacle stopped, and such a contact is reported with {@link #betweenSamples()} true, from
 * the sample before it to the sample after it. (A recorded trace has no such count: only contacts its
 * samples saw are in it.) What was touched is worked out from where the robot, the walls, lamps, caps and
 * other robots were at the sample.
 *
 * @param from simulated time of the first sample that saw the contact (for a contact between samples,
 *     the sample before it)
 * @param to simulated time of the last sample that saw it (for a contact between samples, the sample after it)
 * @param what what was touched
 * @param side the side of the robot that touched, in its own frame: {@code FRONT}, {@code FRONT_LEFT},
 *     {@code LEFT}, {@code BACK_LEFT}, {@code BACK}, {@code BACK_RIGHT}, {@code RIGHT} or {@code FRONT_RIGHT};
 *     {@code UNSEEN} for a contact between samples
 * @param x the robot's centre at {@code from}, mm
 * @param y the robot's centre at {@code from}, mm
 * @param betweenSamples true when no sample saw the robot touching: the simulator counted a move stopped
 *     by an obstacle between two samples
 */
public record Contact(SimTime from, SimTime to, Obstacle what, String side, double x, double y,
        boolean betweenSamples) {

    /** @return e.g. {@code a wall at 12.350 s (front-left side, robot at (100.0, 200.0) mm)} */
    @Override
    public String toString() {
        String when = betweenSamples ? "between " + from + " and " + to
                : from.equals(to) ? "at " + from : "from " + from + " to " + to;
        String s = betweenSamples ? "" : side.toLowerCase(Locale.ROOT).replace('_', '-') + " side, ";
        return String.format(Locale.ROOT, "%s %s (%srobot at (%.1f, %.1f) mm)", what.described(), when, s, x, y);
    }
}
