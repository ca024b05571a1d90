package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.space.ArcTrig;
import org.kheperasim.sim.engine.space.Bodies;

/**
 * A body stalled against another robot's: its last step found it already touching that robot and
 * heading into it, so it did not move, only turned, with no wall within touching reach of any point
 * its next steps could propose. While nothing of that changes (the body, the other robot and the
 * wheel speeds stay as they were), the next step's outcome is decided by one test, whether its move
 * still heads into that robot ({@link Bodies#pressedBy}): the wall and robot look-ups of a full
 * step would find what they found then. Most robot-ticks of a crowd pressing together are such steps.
 *
 * <p>While the robots it may touch do not move either, the stall lasts as many ticks as the move,
 * turning by the same angle every tick, keeps heading into the other robot: {@link #ticks} solves
 * for them, so a unit of robots pressing against each other is driven over them at once.
 */
final class Stall {
    private final Bodies bodies;
    /** The robot it is pressed against, or -1: no stall is known. */
    private int mate = -1;
    private double x;
    private double y;
    private double mateX;
    private double mateY;
    private double left;
    private double right;

    /**
     * After a step that did not move the body at (px, py) because robot {@code k} was in the way of
     * its move of {@code stepLen} mm: remember the stall if no wall can be within touching reach of
     * any point that close to (px, py) (the field's lower bound of each cell there says so).
     */
    Stall(Bodies bodies) {
        this.bodies = bodies;
    }

    void found(int k, DistanceField field, double px, double py, double stepLen, double touch,
            double l, double r) {
        mate = -1;
        double d = StrictMath.abs(stepLen) + 1e-9;
        if (d >= OccupancyGrid.CELL_MM || field.clearanceBelow(px - d, py - d) <= touch
                || field.clearanceBelow(px + d, py - d) <= touch || field.clearanceBelow(px - d, py + d) <= touch
                || field.clearanceBelow(px + d, py + d) <= touch) {
            return;
        }
        mate = k;
        x = px;
        y = py;
        mateX = bodies.x(k);
        mateY = bodies.y(k);
        left = l;
        right = r;
    }

    /** @return the robot {@code body} is still stalled against, or -1 */
    int holds(DriveBody body) {
        Wheels w = body.wheels();
        return mate >= 0 && body.x() == x && body.y() == y && w.left() == left && w.right() == right
                && bodies.x(mate) == mateX && bodies.y(mate) == mateY ? mate : -1;
    }

    /**
     * @return true when the next step of {@code body} (whose last step was blocked) would only turn it on the spot,
     *     as it is still stalled and no cap is near ({@code caps} cleared of a blocking cap, as a step clears it)
     */
    boolean stepIsStalled(DriveBody body, CapContacts caps) {
        int k = holds(body);
        if (k < 0 || !headsInto(body, k, 0)) {
            return false;
        }
        caps.clearBlocking();
        return !caps.near(x, y);
    }

    void forget() {
        mate = -1;
    }

    /** The heading after some stalled ticks. */
    private final ArcTrig ahead = new ArcTrig();

    /**
     * @param body the body, its last step blocked
     * @param wanted the most ticks asked about
     * @return how many of the next ticks, up to {@code wanted}, the body would only turn on the spot,
     *     if nothing else moves: the move turns with the body, and the stall ends with the first tick
     *     whose move no longer heads into the robot it is stalled against (0: none)
     */
    long ticks(DriveBody body, long wanted) {
        int k = holds(body);
        if (k < 0 || !headsInto(body, k, 0)) {
            return 0;
        }
        double perTick = body.wheels().turn(1);
        if (perTick == 0) {
            return wanted;
        }
        // The move's direction turns by perTick a tick; it heads into k while its angle to k's direction stays
        // within (-pi/2, pi/2): estimate the tick it leaves, then find it exactly.
        double step = body.tickStepMm();
        ArcTrig trig = body.arcTrig();
        double c = body.cos();
        double s = body.sin();
        double angle = StrictMath.atan2(s * trig.halfCos + c * trig.halfSin, c * trig.halfCos - s * trig.halfSin)
                - StrictMath.atan2(mateY - body.y(), mateX - body.x()) + (step < 0 ? StrictMath.PI : 0);
        angle = StrictMath.IEEEremainder(angle, 2 * StrictMath.PI);
        double left = perTick > 0 ? StrictMath.PI / 2 - angle : angle + StrictMath.PI / 2;
        long j = (long) StrictMath.min(wanted - 1, StrictMath.max(0, StrictMath.ceil(left / StrictMath.abs(perTick))));
        while (j > 0 && !headsInto(body, k, j - 1)) {
            j--;
        }
        while (j < wanted && headsInto(body, k, j)) {
            j++;
        }
        return j;
    }

    /**
     * @return true when the move of the tick after {@code turned} stalled ticks from now would still head into
     *     robot {@code k}, the body turned as {@link DriveBody#turnStalled} turns it
     */
    private boolean headsInto(DriveBody body, int k, long turned) {
        double c = body.cos();
        double s = body.sin();
        if (turned > 0) {
            ahead.full(body.wheels().turn(turned));
            double tc = c * ahead.fullCos - s * ahead.fullSin;
            double ts = s * ahead.fullCos + c * ahead.fullSin;
            double n = 1.0 / StrictMath.sqrt(tc * tc + ts * ts);
            c = tc * n;
            s = ts * n;
        }
        double step = body.tickStepMm();
        ArcTrig trig = body.arcTrig();
        double x = body.x();
        double y = body.y();
        double tx = x + step * (c * trig.halfCos - s * trig.halfSin) - x;
        double ty = y + step * (s * trig.halfCos + c * trig.halfSin) - y;
        return bodies.pressedBy(k, x, y, body.radius(), tx, ty);
    }
}
