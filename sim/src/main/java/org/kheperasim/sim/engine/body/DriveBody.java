package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.space.ArcTrig;
import org.kheperasim.sim.engine.space.Bodies;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Contact;

/**
 * The robot's body on its two wheels: pose, wheel speeds with their calibration and noise, the exact
 * arc it drives, its clearance from walls and lamps, contact, and the wheel encoders.
 *
 * <p>Two ways to move: {@link #glide} drives an exact arc over any number of ticks when nothing can
 * be touched on the way (the caller has checked {@link #freeTravelMm}); {@link #step} drives one
 * tick with contact handling. Both use the same arithmetic, so a glide over n ticks lands where n
 * steps without contact would, to rounding.
 */
public final class DriveBody {
    /** Closer than this to an obstacle (beyond the body radius) counts as touching. */
    public static final double CONTACT_EPSILON_MM = 0.5;
    /** The fast clearance estimate can exceed the true one by up to 2.2 cells; below this margin, refine. */
    public static final double NEAR_MM = 3 * OccupancyGrid.CELL_MM;
    private static final double TICK_S = Ticks.NANOS / 1e9;

    private final DistanceField field;
    private final double mmPerPulse;
    /** The body's radius and the wheel base, mm (the robot type's). */
    private final double radius;
    private final double wheelBase;
    private final Wheels wheels;

    private double x;
    private double y;
    private double cos;
    private double sin;
    /** The body's clearance from walls and lamps, and its cheap bounds. */
    private final BodyClearance room;
    private double encoderLeft;
    private double encoderRight;
    /**
     * The side of the present contact; null while it is still to be worked out from {@link #touchX}, {@link #touchY}.
     */
    private Contact contact = Contact.NONE;
    private double touchX;
    private double touchY;
    /** The other robots, bodies to this one as walls are; and this robot's index among them. */
    private final Bodies bodies;
    private final int self;
    private boolean blocked;
    private int collisions;
    private double distance;

    /** The last arc's trigonometry, reused while the turn per move does not change. */
    private final ArcTrig trig = new ArcTrig();

    public DriveBody(World world, int self, double x, double y, double headingDeg, RobotType type,
            RobotModel.Motors motors,
            double readingNoise, double calibrationLeft, double calibrationRight, CounterNoise noiseLeft,
            CounterNoise noiseRight) {
        this.field = world.field();
        this.bodies = world.bodies();
        this.self = self;
        this.mmPerPulse = motors.mmPerPulse();
        this.radius = type.body().radiusMm();
        this.wheelBase = type.drive().wheelBaseMm();
        this.wheels = new Wheels(type.drive(), motors, readingNoise, calibrationLeft, calibrationRight,
                noiseLeft, noiseRight);
        this.x = x;
        this.y = y;
        double h = StrictMath.toRadians(headingDeg);
        this.cos = StrictMath.cos(h);
        this.sin = StrictMath.sin(h);
        this.room = new BodyClearance(field, x, y, radius);
        bodies.add(self, x, y, radius);
    }

    /** @return the body's radius, mm */
    public double radius() {
        return radius;
    }

    // ------------------------------------------------------------------ wheels

    /** @return the wheels: their speeds, calibration and noise */
    public Wheels wheels() {
        return wheels;
    }

    private boolean still() {
        return wheels.still();
    }

    /**
     * @return a lower bound of the distance from the centre to the nearest wall or lamp, less the
     *     body radius and the touching margin: the centre can travel that far without a contact, mm
     */
    public double freeTravelMm() {
        return room.freeTravel(x, y);
    }

    /**
     * @param lookUp false: only from the last look-up, less how far the robot has moved since (no
     *     memory touched); true: look the field's bound up here too
     * @return a lower bound of {@link #freeTravelMm}, cheaper (a byte of the distance field at most):
     *     where it already allows what is asked, the exact value is not needed
     */
    public double freeTravelAtLeastMm(boolean lookUp) {
        return room.freeTravelAtLeast(x, y, lookUp);
    }

    // ------------------------------------------------------------------ moving

    /**
     * Drive the exact arc of {@code ticks} ticks at the present wheel speeds, with nothing to touch
     * on the way.
     */
    public void glide(long ticks) {
        if (still()) {
            return;
        }
        double common = arc(ticks);
        double nx = x + common * trig.chord * (cos * trig.halfCos - sin * trig.halfSin);
        double ny = y + common * trig.chord * (sin * trig.halfCos + cos * trig.halfSin);
        turnAndMove(nx, ny, cos * trig.fullCos - sin * trig.fullSin, sin * trig.fullCos + cos * trig.fullSin);
        room.forget();
        count(common, diff(ticks), 1);
        blocked = false;
        contact = Contact.NONE;
    }

    /**
     * Where a glide of {@code ticks} ticks from here would end, without moving: the position and
     * counters {x, y, -, -, left encoder, right encoder} into {@code out} (the heading is
     * {@link #previewHeading}'s). The engine samples sensors inside a glide this way.
     */
    public void previewPosition(long ticks, double[] out) {
        previewCounters(ticks, out);
        if (ticks == 0 || still()) {
            out[0] = x;
            out[1] = y;
            return;
        }
        double common = halfArc(ticks);
        out[0] = x + common * trig.chord * (cos * trig.halfCos - sin * trig.halfSin);
        out[1] = y + common * trig.chord * (sin * trig.halfCos + cos * trig.halfSin);
    }

    /** The heading at the end of a glide of {@code ticks} ticks, {cos, sin} into {@code out[2, 3]}. */
    public void previewHeading(long ticks, double[] out) {
        if (ticks == 0 || still()) {
            out[2] = cos;
            out[3] = sin;
            return;
        }
        trig.full(turn(ticks));
        double c = cos * trig.fullCos - sin * trig.fullSin;
        double s = sin * trig.fullCos + cos * trig.fullSin;
        double n = 1.0 / StrictMath.sqrt(c * c + s * s);
        out[2] = c * n;
        out[3] = s * n;
    }

    /** The counters of {@link #previewPosition} ({@code out[4, 5]}), without the arc's trigonometry. */
    public void previewCounters(long ticks, double[] out) {
        if (ticks == 0 || still()) {
            out[4] = encoderLeft;
            out[5] = encoderRight;
            return;
        }
        double dt = ticks * TICK_S;
        double common = (wheels.left() * dt + wheels.right() * dt) * 0.5;
        double diff = diff(ticks);
        out[4] = encoderLeft + (common - diff) / mmPerPulse;
        out[5] = encoderRight + (common + diff) / mmPerPulse;
    }

    /**
     * Drive one tick with contact handling: a move into a wall or lamp goes only as far as the
     * contact and stops translating (the turn still happens, and the wheels' common motion stalls);
     * caps give way when they can, and one that cannot blocks the robot like a wall.
     *
     * @param caps the caps and the parts of the robot that push them
     * @param mates the only other robots it may touch during this tick (see {@link
     *     Bodies#freeFraction}), or null: any
     * @param mateCount how many of {@code mates} count
     */
    public void step(CapContacts caps, int[] mates, int mateCount) {
        if (still()) {
            return;
        }
        double common = arc(1);
        double diff = diff(1);
        double stepLen = common * trig.chord;
        double midCos = cos * trig.halfCos - sin * trig.halfSin;
        double midSin = sin * trig.halfCos + cos * trig.halfSin;
        double nx = x + stepLen * midCos;
        double ny = y + stepLen * midSin;
        double newClearance = nearWall(nx, ny);
        double fraction = 1;
        boolean nowBlocked = false;
        // NaN compares false: no wall within touch.
        if (newClearance < radius && newClearance < room.here(x, y)) {
            double clearance = room.here(x, y);
            fraction = clearance > radius
                    ? (clearance - radius) / (clearance - newClearance) : 0;
            nx = x + fraction * stepLen * midCos;
            ny = y + fraction * stepLen * midSin;
            newClearance = nearWall(nx, ny);
            nowBlocked = true;
            if (!blocked) {
                collisions++;
            }
        }
        if (bodies.count() > 1) {
            // Another robot stops this one as a wall does: it goes only as far as touching it.
            double tx = nx - x;
            double ty = ny - y;
            double f = bodies.freeFraction(self, x, y, radius, tx, ty, mates, mateCount);
            if (f < 1) {
                nx = x + f * tx;
                ny = y + f * ty;
                fraction *= f;
                newClearance = nearWall(nx, ny);
                if (!nowBlocked && !blocked) {
                    collisions++;
                }
                nowBlocked = true;
            }
        }
        double c = cos * trig.fullCos - sin * trig.fullSin;
        double s = sin * trig.fullCos + cos * trig.fullSin;
        caps.clearBlocking();
        if (caps.near(nx, ny)) {
            double tx = nx - x;
            double ty = ny - y;
            if (!caps.allow(nx, ny, c, s)) {
                if (!caps.allow(x, y, c, s)) {
                    c = cos;
                    s = sin;
                    diff = 0;
                }
                double f = caps.allow(x, y, c, s) ? caps.freeFraction(x, y, tx, ty, c, s) : 0;
                nx = x + f * tx;
                ny = y + f * ty;
                fraction *= f;
                newClearance = nearWall(nx, ny);
                if (!nowBlocked && !blocked) {
                    collisions++;
                }
                nowBlocked = true;
            }
            caps.push(nx, ny, c, s);
        }
        blocked = nowBlocked;
        turnAndMove(nx, ny, c, s);
        if (Double.isNaN(newClearance)) {
            room.forget();
        } else {
            room.set(newClearance);
        }
        count(common, diff, fraction);
        int other = bodies.count() > 1
                ? bodies.firstTouching(self, x, y, radius + CONTACT_EPSILON_MM, mates, mateCount) : -1;
        if (newClearance <= radius + CONTACT_EPSILON_MM) {
            touching(field.nearestObstacleX(x, y), field.nearestObstacleY(x, y));
        } else if (other >= 0) {
            touching(bodies.x(other), bodies.y(other));
        } else if (caps.blocking() >= 0) {
            touching(caps.blockingX(), caps.blockingY());
        } else {
            contact = Contact.NONE;
        }
    }

    /**
     * The clearance of a centre at (px, py), as {@link BodyClearance#at}; or NaN where the field's
     * lower bound proves it farther than touching (then no wall can stop or touch the body there,
     * and the value is looked up only if needed later, at the same place).
     */
    private double nearWall(double px, double py) {
        return field.clearanceBelow(px, py) > radius + CONTACT_EPSILON_MM ? Double.NaN : room.at(px, py);
    }

    /**
     * The body touches something at (ox, oy): the side is worked out when asked for ({@link
     * #contact}), from the pose it has now (it keeps it until the next move, which sets the contact
     * anew), since most contacts are never looked at.
     */
    private void touching(double ox, double oy) {
        contact = null;
        touchX = ox;
        touchY = oy;
    }

    /** Set up the arc of {@code ticks} ticks; returns the centre's path length (signed), mm. */
    private double arc(long ticks) {
        double common = halfArc(ticks);
        trig.full(trig.turn());
        return common;
    }

    /** The half of {@link #arc} that places the centre: the half turn's trigonometry and the chord. */
    private double halfArc(long ticks) {
        double dt = ticks * TICK_S;
        double dl = wheels.left() * dt;
        double dr = wheels.right() * dt;
        trig.half((dr - dl) / wheelBase);
        return (dl + dr) * 0.5;
    }

    /** The turn of an arc of {@code ticks} ticks, rad (as {@link #halfArc} computes it). */
    private double turn(long ticks) {
        double dt = ticks * TICK_S;
        return (wheels.right() * dt - wheels.left() * dt) / wheelBase;
    }

    private double diff(long ticks) {
        return (wheels.right() - wheels.left()) * ticks * TICK_S * 0.5;
    }

    private void turnAndMove(double nx, double ny, double c, double s) {
        double n = 1.0 / StrictMath.sqrt(c * c + s * s);
        x = nx;
        y = ny;
        cos = c * n;
        sin = s * n;
        bodies.moved(self, x, y);
    }

    private void count(double common, double diff, double fraction) {
        double moved = common * fraction;
        encoderLeft += (moved - diff) / mmPerPulse;
        encoderRight += (moved + diff) / mmPerPulse;
        distance += StrictMath.abs(moved);
    }

    /** The arena was edited: check the clearance again. */
    public void arenaEdited() {
        room.arenaEdited(x, y);
    }

    private Contact sideOf(double obstacleX, double obstacleY) {
        double rel = StrictMath.atan2(obstacleY - y, obstacleX - x) - StrictMath.atan2(sin, cos);
        return Contact.ofAngle(rel);
    }

    // ------------------------------------------------------------------ the robot's own counters

    /** Set the position counters ({@code G} arrived), pulses. */
    public void setCounters(int left, int right) {
        encoderLeft = left;
        encoderRight = right;
    }

    /** @return the left counter's exact travel, pulses */
    public double encoderLeftExact() {
        return encoderLeft;
    }

    /** @return the right counter's exact travel, pulses */
    public double encoderRightExact() {
        return encoderRight;
    }

    /** @return the 32-bit counter's value for a wheel travel of {@code count} pulses (it wraps like the robot's) */
    public static int pulses(double count) {
        // Math.floor is exact (as StrictMath.floor), and an intrinsic.
        return (int) (long) Math.floor(count);
    }

    // ------------------------------------------------------------------ views

    public double x() {
        return x;
    }

    public double y() {
        return y;
    }

    public double cos() {
        return cos;
    }

    public double sin() {
        return sin;
    }

    public Contact contact() {
        if (contact == null) {
            contact = sideOf(touchX, touchY);
        }
        return contact;
    }

    public boolean blocked() {
        return blocked;
    }

    public double[] touchPoint() {
        return new double[] {touchX, touchY};
    }

    public int collisions() {
        return collisions;
    }

    public double distanceMm() {
        return distance;
    }
}
