package org.kheperasim.testing;

import java.util.Locale;

/**
 * A time a robot's body touched something.
 *
 * <p>In a run made by a test, from the engine's contact events: {@code from} is the first millisecond tick
 * the robot touched, {@code to} the last (the run's end when it still touches then), whatever the sample
 * period, and a bump that no sample saw is there too, with {@link #betweenSamples()} true. In a recorded
 * trace (which has no events) from its samples: from the first sample that saw it touching to the last,
 * what was touched worked out from where the robot, the walls, lamps, caps and other robots were at the
 * sample; a bump between samples is not seen.
 *
 * @param from simulated time of the first tick (a recording: sample) that saw the contact
 * @param to simulated time of the last tick (a recording: sample) that saw it
 * @param what what was touched
 * @param side the side of the robot that touched, in its own frame: {@code FRONT}, {@code FRONT_LEFT},
 *     {@code LEFT}, {@code BACK_LEFT}, {@code BACK}, {@code BACK_RIGHT}, {@code RIGHT} or {@code FRONT_RIGHT}
 * @param x the robot's centre at {@code from}, mm
 * @param y the robot's centre at {@code from}, mm
 * @param betweenSamples true when no sample of the run's trace saw the robot touching (it began and ended
 *     between two samples)
 */
public record Contact(SimTime from, SimTime to, Obstacle what, String side, double x, double y,
        boolean betweenSamples) {

    /** @return e.g. {@code a wall at 12.350 s (front-left side, robot at (100.0, 200.0) mm)} */
    @Override
    public String toString() {
        String when = (from.equals(to) ? "at " + from : "from " + from + " to " + to)
                + (betweenSamples ? " (between samples)" : "");
        String s = side.toLowerCase(Locale.ROOT).replace('_', '-') + " side, ";
        return String.format(Locale.ROOT, "%s %s (%srobot at (%.1f, %.1f) mm)", what.described(), when, s, x, y);
    }
}
