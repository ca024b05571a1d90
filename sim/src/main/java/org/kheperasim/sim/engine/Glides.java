package org.kheperasim.sim.engine;

/**
 * How far a robot may glide along its arc before anything could happen that needs a tick-by-tick
 * step: a contact with a wall, a lamp, a cap or another robot, another robot coming into sight, a
 * region entered, the gripper moving. Cheap bounds are asked first; the exact clearance only when
 * they would cut the glide short.
 */
final class Glides {
    /** How far it looks for other robots when it glides, mm. */
    private static final double LOOK_MM = 400;

    private final int id;
    private final RobotModel model;
    private final DriveBody body;
    private final GripperModel gripper;
    private final CapContacts capContacts;
    private final Coverage coverage;
    private final Bodies bodies;
    /** Another robot's surface farther than this from the centre is out of every sensor's reach, mm. */
    private final double unseenMm;

    Glides(int id, RobotModel model, DriveBody body, GripperModel gripper, CapContacts capContacts, Coverage coverage,
            Bodies bodies, double unseenMm) {
        this.id = id;
        this.model = model;
        this.body = body;
        this.gripper = gripper;
        this.capContacts = capContacts;
        this.coverage = coverage;
        this.bodies = bodies;
        this.unseenMm = unseenMm;
    }

    /**
     * @param wanted how many ticks the caller would glide at most
     * @return how many ticks the robot can glide from here along its arc with nothing to touch and
     *     no region to enter on the way (0: the next tick must be stepped with contact handling), or
     *     any number of at least {@code wanted} when it can glide that far
     */
    long ticks(long wanted) {
        return ticks(wanted, false);
    }

    /**
     * @param othersApart true when the caller knows that no other robot can come within touch of
     *     this one while it glides, nor a sample be taken on the way: the other robots then set no bound
     */
    long ticks(long wanted, boolean othersApart) {
        if (model.stepping() == RobotModel.Stepping.TICK || gripper.busy()) {
            return 0;
        }
        if (body.still()) {
            return Long.MAX_VALUE;
        }
        double others = StrictMath.min(othersApart ? Double.POSITIVE_INFINITY : othersFreeTravelMm(),
                StrictMath.min(capContacts.freeTravelMm(body.x(), body.y()), coverage.freeTravelMm(body.x(), body.y())));
        // The body's clearance is looked up only when its cheap lower bound does not already allow the glide wanted.
        long ticks = glideTicksFor(StrictMath.min(body.freeTravelAtLeastMm(false), others));
        if (ticks >= wanted) {
            return ticks;
        }
        ticks = glideTicksFor(StrictMath.min(body.freeTravelAtLeastMm(true), others));
        return ticks >= wanted ? ticks : glideTicksFor(StrictMath.min(body.freeTravelMm(), others));
    }

    private long glideTicksFor(double free) {
        double ticks = (free - 1e-6) / body.travelPerTickMm();
        return ticks >= 1 ? (long) StrictMath.min(ticks, 1e15) : 0;
    }

    /**
     * How far this robot may glide with the other robots in mind: while it glides they stay out of
     * its sensors' reach and it out of theirs, so no beam could see a robot in between. Every robot
     * that moves takes at most half the gap to its nearest neighbour, so two of them never close it.
     */
    private double othersFreeTravelMm() {
        if (bodies.count() < 2) {
            return Double.POSITIVE_INFINITY;
        }
        double gap = bodies.surface(id, body.x(), body.y(), LOOK_MM);
        return (StrictMath.min(gap, LOOK_MM) - unseenMm) * 0.5;
    }
}
