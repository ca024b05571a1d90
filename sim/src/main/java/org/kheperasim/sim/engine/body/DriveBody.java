package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.model.RobotModel;
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
 * steps without contact would, to rounding. A body stalled against another robot (it touches it and
 * its move heads into it: it only turns) is a third: {@link #stalledTicks} solves how long the stall
 * lasts while the robots it may touch do not move, and {@link #turnStalled} drives those ticks at once.
 */
public final class DriveBody {
    /** Closer than this to an obstacle (beyond the body radius) counts as touching. */
    public static final double CONTACT_EPSILON_MM = 0.5;
    /** The fast clearance estimate can exceed the true one by up to 2.2 cells; below this margin, refine. */
    public static final double NEAR_MM = 3 * OccupancyGrid.CELL_MM;

    private final DistanceField field;
    /** The body's radius, mm (the robot type's). */
    private final double radius;
    private final Wheels wheels;

    private double x;
    private double y;
    private double cos;
    private double sin;
    /** The body's clearance from walls and lamps, and its cheap bounds. */
    private final BodyClearance room;
    /** What it touches. */
    private final Touch touch = new Touch();
    /** The other robots, bodies to this one as walls are; and this robot's index among them. */
    private final Bodies bodies;
    private final int self;
    private boolean blocked;
    private int collisions;
    /** The encoders' travel and the centre's. */
    private final Odometry odometry;

    /** The last arc's trigonometry, reused while the turn per move does not change. */
    private final ArcTrig trig = new ArcTrig();
    private final GlidePreview preview = new GlidePreview(this);
    /** A stall against another robot found by the last step, so the next decides it with one test. */
    private final Stall stall;

    public DriveBody(World world, int self, double x, double y, double headingDeg, RobotType type,
            RobotModel.Motors motors,
            double readingNoise, double calibrationLeft, double calibrationRight, CounterNoise noiseLeft,
            CounterNoise noiseRight) {
        this.field = world.field();
        this.bodies = world.bodies();
        this.self = self;
        this.odometry = new Odometry(motors.mmPerPulse());
        this.radius = type.body().radiusMm();
        this.wheels = new Wheels(type.drive(), motors, readingNoise, calibrationLeft, calibrationRight,
                noiseLeft, noiseRight);
        this.x = x;
        this.y = y;
        double h = StrictMath.toRadians(headingDeg);
        this.cos = StrictMath.cos(h);
        this.sin = StrictMath.sin(h);
        this.room = new BodyClearance(field, x, y, radius);
        this.stall = new Stall(bodies);
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
        odometry.count(common, wheels.diff(ticks), 1);
        blocked = false;
        touch.none();
    }

    /** @return where a glide from here would end, for samples taken inside it */
    public GlidePreview preview() {
        return preview;
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
        if (mates != null && blocked && stall.stepIsStalled(this, caps)) {
            turnStalled(1, caps, mates, mateCount);
            return;
        }
        double common = arc(1);
        double diff = wheels.diff(1);
        double stepLen = common * trig.chord;
        double midCos = cos * trig.halfCos - sin * trig.halfSin;
        double midSin = sin * trig.halfCos + cos * trig.halfSin;
        double nx = x + stepLen * midCos;
        double ny = y + stepLen * midSin;
        double newClearance = nearWall(nx, ny);
        double fraction = 1;
        boolean nowBlocked = false;
        int stalled = -1;
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
            if (f == 0 && !nowBlocked && mates != null) {
                stalled = bodies.pressing(self, x, y, radius, tx, ty, mates, mateCount);
            }
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
            stalled = -1;
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
        if (stalled >= 0) {
            stall.found(stalled, field, x, y, stepLen, radius + CONTACT_EPSILON_MM, wheels.left(),
                    wheels.right());
        } else {
            stall.forget();
        }
        turnAndMove(nx, ny, c, s);
        if (Double.isNaN(newClearance)) {
            room.forget();
        } else {
            room.set(newClearance);
        }
        odometry.count(common, diff, fraction);
        int other = bodies.count() > 1
                ? bodies.firstTouching(self, x, y, radius + CONTACT_EPSILON_MM, mates, mateCount) : -1;
        if (newClearance <= radius + CONTACT_EPSILON_MM) {
            touch.at(field.nearestObstacleX(x, y), field.nearestObstacleY(x, y));
        } else if (other >= 0) {
            touch.at(bodies.x(other), bodies.y(other));
        } else if (caps.blocking() >= 0) {
            touch.at(caps.blockingX(), caps.blockingY());
        } else {
            touch.none();
        }
    }

    /**
     * @param wanted the most ticks the caller asks about
     * @return how many of the next ticks, up to {@code wanted}, the body would only turn on the spot:
     *     its wheels are still, or it is stalled against a robot ({@link Stall}) and its move keeps heading into
     *     it; valid while no body of the robots it may touch moves meanwhile. {@link #turnStalled} then drives
     *     them at once (their turn in closed form, as a glide's)
     */
    public long stalledTicks(long wanted) {
        if (still()) {
            return wanted;
        }
        return blocked ? stall.ticks(this, wanted) : 0;
    }

    /** @return the centre's step over the next tick at the present speeds (signed), mm; sets {@link #arcTrig} */
    double tickStepMm() {
        return halfArc(1) * trig.chord;
    }

    /** @return the trigonometry of the next tick's arc (after {@link #tickStepMm}) */
    ArcTrig arcTrig() {
        return trig;
    }

    /** @return the centre's path length over {@code ticks} ticks (signed), mm; {@link #arcTrig} has its half turn */
    double halfArcOf(long ticks) {
        return halfArc(ticks);
    }

    Odometry odometry() {
        return odometry;
    }

    /**
     * Drive {@code ticks} ticks that {@link #stalledTicks} allows: the body turns on the spot, its counters
     * count the turn, and it goes on touching what it touched.
     */
    public void turnStalled(long ticks, CapContacts caps, int[] mates, int mateCount) {
        if (still() || ticks == 0) {
            return;
        }
        trig.full(wheels.turn(ticks));
        double c = cos * trig.fullCos - sin * trig.fullSin;
        double s = sin * trig.fullCos + cos * trig.fullSin;
        double n = 1.0 / StrictMath.sqrt(c * c + s * s);
        cos = c * n;
        sin = s * n;
        room.forget();
        caps.clearBlocking();
        odometry.count(wheels.common(ticks), wheels.diff(ticks), 0.0);
        int other = bodies.firstTouching(self, x, y, radius + CONTACT_EPSILON_MM, mates, mateCount);
        if (other >= 0) {
            touch.at(bodies.x(other), bodies.y(other));
        } else {
            touch.none();
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

    /** Set up the arc of {@code ticks} ticks; returns the centre's path length (signed), mm. */
    private double arc(long ticks) {
        double common = halfArc(ticks);
        trig.full(trig.turn());
        return common;
    }

    /** The half of {@link #arc} that places the centre: the half turn's trigonometry and the chord. */
    private double halfArc(long ticks) {
        trig.half(wheels.turn(ticks));
        return wheels.common(ticks);
    }

    private void turnAndMove(double nx, double ny, double c, double s) {
        double n = 1.0 / StrictMath.sqrt(c * c + s * s);
        x = nx;
        y = ny;
        cos = c * n;
        sin = s * n;
        bodies.moved(self, x, y);
    }

    /** The arena was edited: check the clearance again. */
    public void arenaEdited() {
        stall.forget();
        room.arenaEdited(x, y);
    }

    // ------------------------------------------------------------------ the robot's own counters

    /** Set the position counters ({@code G} arrived), pulses. */
    public void setCounters(int left, int right) {
        odometry.set(left, right);
    }

    /** @return the left counter's exact travel, pulses */
    public double encoderLeftExact() {
        return odometry.left();
    }

    /** @return the right counter's exact travel, pulses */
    public double encoderRightExact() {
        return odometry.right();
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
        return touch.side(x, y, cos, sin);
    }

    /** @return true when the body may be only turning on the spot: its wheels are still, or it is stalled */
    public boolean frozen() {
        return still() || blocked && stall.holds(this) >= 0;
    }

    public boolean blocked() {
        return blocked;
    }

    public double[] touchPoint() {
        return touch.point();
    }

    public int collisions() {
        return collisions;
    }

    public double distanceMm() {
        return odometry.distanceMm();
    }
}
