package org.kheperasim.testing;

import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.testkit.KitRegion;

/**
 * A region that was entered, to say by when: {@code assertThat(run).entered("goal").before(seconds(60))}.
 * Made by {@link RunAssert#entered}; every other check of {@link RunAssert} can follow it.
 */
public final class EntryAssert extends RunAssert {
    private final String region;
    private final RobotRun first;
    private final SimTime at;

    EntryAssert(Run run, List<RobotRun> robots, String region, RobotRun first, SimTime at) {
        super(run, robots);
        this.region = region;
        this.first = first;
        this.at = at;
    }

    /**
     * The region was entered before this simulated time (strictly: entering at {@code deadline} is too late).
     *
     * @param deadline simulated time since the run's start, e.g. {@code seconds(60)}
     * @return the run's assertions, for the next check
     */
    public RunAssert before(SimTime deadline) {
        if (!at.isBefore(deadline)) {
            KitRegion g = run.region(region);
            Pose then = first.poseAt(deadline);
            throw Failure.of(first.name() + " entered region '" + region + "' too late, at " + at + ".")
                    .expected("to enter region '" + region + "' " + bounds(g) + " before " + deadline)
                    .happened(String.format(Locale.ROOT,
                            "first entered at %s; at %s the robot was at %s, %.1f mm from the"
                            + " region", at, deadline, then, RunShapes.distanceTo(then.x(), then.y(), g)))
                    .raise(run);
        }
        return new RunAssert(run, robots);
    }

    /** @return when the region was first entered (by the first robot to enter it) */
    public SimTime time() {
        return at;
    }
}
