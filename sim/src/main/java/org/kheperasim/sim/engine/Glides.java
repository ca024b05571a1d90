package org.kheperasim.sim.engine;

import org.kheperasim.sim.engine.body.CapContacts;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.sensing.Coverage;

/**
 * How far a robot may glide along its arc before anything could happen that needs a tick-by-tick
 * step: a contact with a wall, a lamp or a cap, a region entered, the gripper moving. Cheap bounds
 * are asked first; the exact clearance only when they would cut the glide short. The other robots
 * are not its concern: the engine moves a robot on its own only through stretches in which no
 * other robot can touch it ({@link Motion}, {@link Crowd}).
 */
final class Glides {
    private final RobotModel model;
    private final DriveBody body;
    private final GripperModel gripper;
    private final CapContacts capContacts;
    private final Coverage coverage;

    Glides(RobotModel model, DriveBody body, GripperModel gripper, CapContacts capContacts, Coverage coverage) {
        this.model = model;
        this.body = body;
        this.gripper = gripper;
        this.capContacts = capContacts;
        this.coverage = coverage;
    }

    /**
     * @param wanted how many ticks the caller would glide at most
     * @return how many ticks the robot can glide from here along its arc with nothing to touch and
     *     no region to enter on the way (0: the next tick must be stepped with contact handling), or
     *     any number of at least {@code wanted} when it can glide that far
     */
    long ticks(long wanted) {
        if (model.stepping() == RobotModel.Stepping.TICK || gripper.busy()) {
            return 0;
        }
        if (body.wheels().still()) {
            return Long.MAX_VALUE;
        }
        double others = StrictMath.min(capContacts.freeTravelMm(body.x(), body.y()),
                coverage.freeTravelMm(body.x(), body.y()));
        // The body's clearance is looked up only when its cheap lower bound does not already allow the glide wanted.
        long ticks = glideTicksFor(StrictMath.min(body.freeTravelAtLeastMm(false), others));
        if (ticks >= wanted) {
            return ticks;
        }
        ticks = glideTicksFor(StrictMath.min(body.freeTravelAtLeastMm(true), others));
        return ticks >= wanted ? ticks : glideTicksFor(StrictMath.min(body.freeTravelMm(), others));
    }

    private long glideTicksFor(double free) {
        double ticks = (free - 1e-6) / body.wheels().travelPerTickMm();
        return ticks >= 1 ? (long) StrictMath.min(ticks, 1e15) : 0;
    }
}
