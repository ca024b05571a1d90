package org.kheperasim.controllers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.SensorFilter;

/**
 * Gathers the bottle caps of the {@code two-rooms} arena into the lit room (the paper's second
 * assignment). Wandering at random finds most caps quickly and the last one late or never; this
 * controller searches instead, the way a farmer ploughs a field:
 *
 * <ol>
 *   <li><b>Sweep.</b> It drives up and down the left room in lanes 100 mm apart, arm down and
 *       fingers open, keeping track of where it is by {@link Odometry}. Its side and front
 *       proximity sensors see a cap up to about 70 mm to either side.</li>
 *   <li><b>Tell a cap from a wall.</b> It knows where the room's walls are (the layout below, as a
 *       student would measure it in the lab), so a sensor that sees something where its beam cannot
 *       yet reach a wall is seeing a cap.</li>
 *   <li><b>Approach.</b> It turns toward the cap, scans slowly across it and faces the heading at
 *       which the two front sensors see the most, then creeps forward until the cap breaks the
 *       optical barrier between the fingers. It closes them; resistivity says whether it holds a cap.
 *       A spot where the approach fails twice is not tried again (a cap jammed in a corner, or a wall
 *       end mistaken for a cap), so it can never livelock there.</li>
 *   <li><b>Deliver.</b> Arm up, it drives through the doorway and puts the cap down on the next free
 *       spot of a ring around the doorway's exit (each cap on its own spoke, so the way to the next
 *       spot is never blocked by the caps already there), backs off, and returns to where the sweep
 *       left off. When a sweep ends it starts another, with lanes halfway between the last ones.</li>
 * </ol>
 *
 * <p>Only the robot's own sensors are used (encoders, proximity, the gripper's barrier and
 * resistivity), so it runs unchanged on a real Khepera with a gripper turret. In the simulator the
 * encoders count exactly what the wheels did; on the real robot wheels slip, and over a long run
 * odometry drifts: a good exercise is to correct it whenever the robot meets a wall.
 */
public class CapGatherer extends Controller {
    // ---- The arena as measured (two-rooms), in arena coordinates, mm. The robot starts at
    //      (START_X, START_Y) facing along x; odometry carries on from there. ----
    private static final double START_X = 300;
    private static final double START_Y = 609.6;
    /** The inside faces of the left room's walls. */
    private static final double ROOM_LEFT = 8;
    private static final double ROOM_RIGHT = 605.6;
    private static final double ROOM_BOTTOM = 8;
    private static final double ROOM_TOP = 1211.2;
    /** The doorway in the dividing wall, between the faces of its two wall ends. */
    private static final double DOOR_LOW = 513.6;
    private static final double DOOR_HIGH = 705.6;
    private static final double DOOR_Y = 609.6;
    /** Points on the doorway's axis to pass through, before and after it. */
    private static final double BEFORE_DOOR_X = 540;
    private static final double AFTER_DOOR_X = 700;
    /** The sweeps' lanes (x of each), alternately. */
    private static final double[][] LANES = {{60, 160, 260, 360, 460, 560}, {110, 210, 310, 410, 510}};
    private static final double LANE_LOW = 70;
    private static final double LANE_HIGH = 1150;
    /** The spokes of the ring of drop spots around the doorway's exit, degrees. */
    private static final int[] DROP_ANGLES = {-60, 60, -30, 30, 0, -45, 45, -15, 15, -75, 75};

    // ---- The robot. ----
    /** Where a gripped cap's centre is, mm ahead of the robot's centre. */
    private static final double GRIP_MM = 36.5;
    private static final int STEP_MS = 20;
    private static final int SWEEP_SPEED = 6;
    private static final int TRAVEL_SPEED = 10;
    /** A filtered proximity reading above this sees something (open floor reads about 20). */
    private static final int SEEN = 90;
    /** A sensor whose beam meets a wall within this distance cannot tell a cap from the wall. */
    private static final double WALL_BLIND_MM = 90;
    /** Steps (20 ms each) of wheels turning without moving that count as stuck. */
    private static final int STUCK_STEPS = 50;

    private enum Outcome { ARRIVED, CAP_SEEN, BARRIER, STUCK, STOPPED }

    /** A median of five: the sensors refresh about every 24 ms and are read every 20 ms. */
    private final SensorFilter prox = new SensorFilter(IrSensor.COUNT, 5, SensorFilter.DEFAULT_SPIKE);
    private final FailedSpots failed = new FailedSpots();
    private Odometry odometry;
    private int sweep;
    private int lane;
    private boolean goingUp = true;
    /** Where on the current lane to come back to after a detour, or NaN. */
    private double resumeY = Double.NaN;
    private int delivered;
    private int seenBy;
    private int stuckSteps;
    private boolean armDown;

    @Override
    protected void setup() {
        odometry = new Odometry(START_X, START_Y, 0, leftPosition(), rightPosition());
        release();
        armDown();
        print("sweeping the left room for caps");
    }

    @Override
    protected void doWork() {
        double laneX = LANES[sweep][lane];
        if (!Double.isNaN(resumeY)) {
            Outcome back = driveTo(laneX, resumeY, TRAVEL_SPEED, true);
            if (back != Outcome.ARRIVED) {
                detour(back);
                return;
            }
            resumeY = Double.NaN;
        }
        Outcome along = driveTo(laneX, goingUp ? LANE_HIGH : LANE_LOW, SWEEP_SPEED, true);
        if (along == Outcome.ARRIVED) {
            nextLane();
        } else {
            detour(along);
        }
    }

    private void nextLane() {
        goingUp = !goingUp;
        lane++;
        if (lane == LANES[sweep].length) {
            sweep = (sweep + 1) % LANES.length;
            lane = 0;
            print("sweep done; " + delivered + " caps delivered so far");
        }
        resumeY = odometry.y();
    }

    /** Leave the lane for a cap (or to get unstuck); the lane is taken up again where it was left. */
    private void detour(Outcome why) {
        resumeY = StrictMath.max(LANE_LOW, StrictMath.min(LANE_HIGH, odometry.y()));
        if (why == Outcome.CAP_SEEN) {
            double[] where = seenAt(IrSensor.of(seenBy));
            if (approach()) {
                deliver();
            } else {
                failed.note(where[0], where[1]);
            }
        } else if (why == Outcome.BARRIER) {
            if (grabHere()) {
                deliver();
            }
        } else if (why == Outcome.STUCK) {
            escape();
        }
    }

    /** Turn toward what was seen, find its bearing by a scan, and creep until it is between the fingers. */
    private boolean approach() {
        turnTo(odometry.heading() + StrictMath.toRadians(IrSensor.of(seenBy).headingDeg()));
        for (int attempt = 0; attempt < 2; attempt++) {
            double bearing = scan();
            if (Double.isNaN(bearing)) {
                return false;
            }
            turnTo(bearing);
            double x0 = odometry.x();
            double y0 = odometry.y();
            while (isActive() && odometry.distanceTo(x0, y0) < 70 && stuckSteps < STUCK_STEPS) {
                step();
                if (objectBetweenFingers()) {
                    return grabHere();
                }
                int turn = clamp((int) StrictMath.round(Odometry.wrap(bearing - odometry.heading()) * 10), 1);
                setSpeeds(2 - turn, 2 + turn);
            }
            stopMotors();
            backTo(x0, y0);
        }
        return false;
    }

    /**
     * Turn slowly from half a radian right of the present heading to half a radian left of it,
     * watching the two front sensors.
     *
     * @return the middle of the headings at which they saw at least 80 % of their most, or NaN when
     *     they saw nothing
     */
    private double scan() {
        double centre = odometry.heading();
        turnTo(centre - 0.5);
        double[] headings = new double[400];
        int[] sums = new int[headings.length];
        int n = 0;
        int most = 0;
        while (isActive() && Odometry.wrap(centre + 0.5 - odometry.heading()) > 0 && n < headings.length) {
            setSpeeds(-1, 1);
            step();
            headings[n] = Odometry.wrap(odometry.heading() - centre);
            sums[n] = prox.value(IrSensor.FRONT_LEFT) + prox.value(IrSensor.FRONT_RIGHT);
            most = StrictMath.max(most, sums[n++]);
        }
        stopMotors();
        if (most < 2 * SEEN) {
            return Double.NaN;
        }
        double total = 0;
        int count = 0;
        for (int i = 0; i < n; i++) {
            if (sums[i] >= 0.8 * most) {
                total += headings[i];
                count++;
            }
        }
        return centre + total / count;
    }

    /** Close the fingers on whatever broke the barrier. @return true when it is a cap, now held up */
    private boolean grabHere() {
        stopMotors();
        if (grab() && gripper().getResistivity() > 0) {
            armUp();
            print("got a cap at (" + Math.round(odometry.x()) + ", " + Math.round(odometry.y()) + ")");
            return true;
        }
        release();
        double h = odometry.heading();
        backTo(odometry.x() - 40 * StrictMath.cos(h), odometry.y() - 40 * StrictMath.sin(h));
        return false;
    }

    /** Carry the held cap through the doorway, put it down on the next spot of the ring, and come back. */
    private void deliver() {
        travel(BEFORE_DOOR_X, DOOR_Y);
        travel(AFTER_DOOR_X, DOOR_Y);
        double spoke = StrictMath.toRadians(DROP_ANGLES[delivered % DROP_ANGLES.length]);
        double radius = delivered < 5 ? 170 : 280;
        double cos = StrictMath.cos(spoke);
        double sin = StrictMath.sin(spoke);
        travel(AFTER_DOOR_X + (radius - GRIP_MM) * cos, DOOR_Y + (radius - GRIP_MM) * sin);
        turnTo(spoke);
        armDown();
        release();
        delivered++;
        print("delivered cap " + delivered);
        backTo(AFTER_DOOR_X + (radius - 100) * cos, DOOR_Y + (radius - 100) * sin);
        armUp();
        travel(AFTER_DOOR_X, DOOR_Y);
        travel(BEFORE_DOOR_X, DOOR_Y);
        armDown();
    }

    /** Drive to a point, getting round whatever blocks the way (a cap pushed into a corner). */
    private void travel(double x, double y) {
        for (int tries = 0; tries < 20 && isActive(); tries++) {
            if (driveTo(x, y, TRAVEL_SPEED, false) == Outcome.ARRIVED) {
                return;
            }
            escape();
        }
    }

    /**
     * Drive to (x, y), steering in proportion to the bearing error and slowing down near the end.
     *
     * @param watch stop for a cap seen or one between the fingers
     */
    private Outcome driveTo(double x, double y, int speed, boolean watch) {
        stuckSteps = 0;
        while (isActive()) {
            step();
            double distance = odometry.distanceTo(x, y);
            if (distance < 6) {
                return Outcome.ARRIVED;
            }
            double error = odometry.bearingTo(x, y);
            if (StrictMath.abs(error) > 0.5) {
                turnTo(odometry.heading() + error);
                continue;
            }
            if (watch && odometry.x() < ROOM_RIGHT - 30) {
                if (armDown && objectBetweenFingers()) {
                    stopMotors();
                    return Outcome.BARRIER;
                }
                if (capSeen()) {
                    stopMotors();
                    return Outcome.CAP_SEEN;
                }
            }
            if (stuckSteps > STUCK_STEPS) {
                stopMotors();
                return Outcome.STUCK;
            }
            int v = (int) StrictMath.max(2, StrictMath.min(speed, distance / 8));
            int turn = clamp((int) StrictMath.round(error * 12), 3);
            setSpeeds(v - turn, v + turn);
        }
        return Outcome.STOPPED;
    }

    /** Turn on the spot to a heading, slowing down as it comes near (the encoders arrive late). */
    private void turnTo(double heading) {
        for (int i = 0; i < 1000 && isActive(); i++) {
            step();
            double error = Odometry.wrap(heading - odometry.heading());
            if (StrictMath.abs(error) < 0.02) {
                break;
            }
            int s = (int) StrictMath.max(1, StrictMath.min(5, StrictMath.abs(error) * 6));
            setSpeeds(error > 0 ? -s : s, error > 0 ? s : -s);
        }
        stopMotors();
    }

    /** Reverse straight back to (x, y). */
    private void backTo(double x, double y) {
        for (int i = 0; i < 500 && isActive() && odometry.distanceTo(x, y) > 4; i++) {
            setSpeeds(-4, -4);
            step();
        }
        stopMotors();
    }

    /** Back off, turn, and drive a little way another way. */
    private void escape() {
        double h = odometry.heading();
        backTo(odometry.x() - 50 * StrictMath.cos(h), odometry.y() - 50 * StrictMath.sin(h));
        turnTo(odometry.heading() + (delivered % 2 == 0 ? 0.8 : -0.8));
        h = odometry.heading();
        driveTo(odometry.x() + 60 * StrictMath.cos(h), odometry.y() + 60 * StrictMath.sin(h), 4, false);
    }

    /** @return true when one of the six front sensors sees something that is not a wall (sets seenBy) */
    private boolean capSeen() {
        for (int i = 0; i < 6; i++) {
            IrSensor sensor = IrSensor.of(i);
            if (prox.value(sensor) > SEEN && wallDistance(sensor) > WALL_BLIND_MM) {
                double[] p = seenAt(sensor);
                if (!failed.givenUp(p[0], p[1])) {
                    seenBy = i;
                    return true;
                }
            }
        }
        return false;
    }

    /** @return the point 35 mm out along a sensor's beam: about where a cap it sees is */
    private double[] seenAt(IrSensor s) {
        double[] beam = beam(s);
        return new double[] {beam[0] + 35 * beam[2], beam[1] + 35 * beam[3]};
    }

    /** @return how far a sensor's beam goes before it meets a wall of the left room (or a doorway's wall end), mm */
    private double wallDistance(IrSensor s) {
        double[] beam = beam(s);
        double sx = beam[0];
        double sy = beam[1];
        double dx = beam[2];
        double dy = beam[3];
        double d = Double.POSITIVE_INFINITY;
        if (dx < 0) {
            d = (ROOM_LEFT - sx) / dx;
        } else if (dx > 0) {
            double t = (ROOM_RIGHT - sx) / dx;
            double yThere = sy + t * dy;
            if (yThere < DOOR_LOW + 20 || yThere > DOOR_HIGH - 20) {
                d = t;
            }
        }
        for (double endY : new double[] {DOOR_LOW - 4, DOOR_HIGH + 4}) {
            // The wall ends beside the doorway: corners a beam sees round.
            double along = (ROOM_RIGHT + 4 - sx) * dx + (endY - sy) * dy;
            double off = StrictMath.abs((ROOM_RIGHT + 4 - sx) * dy - (endY - sy) * dx);
            if (along > 0 && off < 15) {
                d = StrictMath.min(d, along);
            }
        }
        if (dy < 0) {
            d = StrictMath.min(d, (ROOM_BOTTOM - sy) / dy);
        } else if (dy > 0) {
            d = StrictMath.min(d, (ROOM_TOP - sy) / dy);
        }
        return d;
    }

    /** @return {x, y, dx, dy}: where a sensor is in the arena and which way it looks */
    private double[] beam(IrSensor s) {
        double c = StrictMath.cos(odometry.heading());
        double n = StrictMath.sin(odometry.heading());
        double h = odometry.heading() + StrictMath.toRadians(s.headingDeg());
        return new double[] {odometry.x() + c * s.xMm() - n * s.yMm(), odometry.y() + n * s.xMm() + c * s.yMm(),
            StrictMath.cos(h), StrictMath.sin(h)};
    }

    private void armDown() {
        lowerArm();
        armDown = true;
    }

    private void armUp() {
        raiseArm();
        armDown = false;
    }

    /** One control step: wait, then read the encoders and the proximity sensors. */
    private void step() {
        sleepMillis(STEP_MS);
        odometry.update(leftPosition(), rightPosition());
        prox.addProximity(sensors());
        boolean driving = motor().getLeftSpeed() != 0 || motor().getRightSpeed() != 0;
        stuckSteps = driving && odometry.lastStep() < 0.1 ? stuckSteps + 1 : 0;
    }

    private static int clamp(int v, int limit) {
        return StrictMath.max(-limit, StrictMath.min(limit, v));
    }
}
