package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.space.Caps;

/**
 * How one robot meets the caps on the floor: which of its parts push (the body always; the lowered
 * fingers and a cap held low when the arm is down), whether the caps it would overlap can give way,
 * and the push itself. Caps that cannot give way block the robot like a wall.
 */
public final class CapContacts {
    /** Bisection steps when a move stops part-way at a cap (2⁻⁸ of a tick's step: well under a micrometre). */
    private static final int BISECT = 8;

    private final Caps caps;
    private final GripperModel gripper;
    private final double[] push = new double[2];
    private int blocking = -1;
    // Caps near the robot: recheck only after moving `slack` mm or when a cap has moved.
    private int checkedVersion = -1;
    private double checkX;
    private double checkY;
    private double slack;
    /** The parts' reach when {@link #near} last looked: lowering the arm or gripping a cap widens it. */
    private double checkedReach;

    /** The robot whose parts push: other robots block the caps it pushes. */
    private final int robot;
    /** The robot's body radius, mm. */
    private final double bodyRadius;

    public CapContacts(Caps caps, GripperModel gripper, int robot, double bodyRadius) {
        this.bodyRadius = bodyRadius;
        this.caps = caps;
        this.gripper = gripper;
        this.robot = robot;
    }

    /**
     * @return how far any pushing part reaches from the robot's centre now, mm: the body, or with the
     *     arm low the fingers' tips (wider apart round a large cap held) and the cap held
     */
    double reachMm() {
        if (!gripper.armLow()) {
            return bodyRadius;
        }
        int held = gripper.heldCap();
        if (held < 0) {
            return GripperTurret.REACH_MM;
        }
        double r = caps.radius(held);
        double half = StrictMath.max(GripperTurret.OPEN_HALF_GAP_MM, r + GripperTurret.FINGER_RADIUS_MM);
        return StrictMath.max(GripperTurret.GRIP_MM + r,
                StrictMath.hypot(GripperTurret.FINGER_TIP_MM, half) + GripperTurret.FINGER_RADIUS_MM);
    }

    /**
     * @return how far the robot's centre can travel from (px, py) before any of its parts could
     *     touch a cap on the floor, mm (infinite with no caps)
     */
    public double freeTravelMm(double px, double py) {
        return caps.count() == 0 ? Double.POSITIVE_INFINITY : caps.nearestSurface(px, py) - reachMm();
    }

    void clearBlocking() {
        blocking = -1;
    }

    /** @return the cap that blocked the last move, or -1 */
    int blocking() {
        return blocking;
    }

    double blockingX() {
        return caps.x(blocking);
    }

    double blockingY() {
        return caps.y(blocking);
    }

    /**
     * Whether a cap could touch the robot at (px, py) in any heading. Cheap when none is near: the
     * answer holds until the robot has moved by the distance to the nearest cap, a cap has moved or
     * the gripper's reach has changed.
     */
    boolean near(double px, double py) {
        if (caps.count() == 0) {
            return false;
        }
        double dx = px - checkX;
        double dy = py - checkY;
        double reach = reachMm();
        if (caps.version() == checkedVersion && reach == checkedReach && dx * dx + dy * dy < slack * slack) {
            return false;
        }
        checkedVersion = caps.version();
        checkedReach = reach;
        checkX = px;
        checkY = py;
        double gap = freeTravelMm(px, py);
        slack = gap > 0 ? gap : 0;
        return gap <= 0;
    }

    /** Forget the cached answer of {@link #near} (the arena was edited). */
    public void forget() {
        checkedVersion = -1;
    }

    /** The parts that push caps: 0 the body, 1 and 2 the lowered fingers, 3 a cap held low. */
    private int pusherCount() {
        if (!gripper.armLow()) {
            return 1;
        }
        return gripper.heldCap() >= 0 ? 4 : 3;
    }

    /** Whether every cap the robot at this pose overlaps can give way (nothing moves). */
    boolean allow(double px, double py, double pc, double ps) {
        int parts = pusherCount();
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            for (int part = 0; part < parts; part++) {
                if (overlap(part, px, py, pc, ps, i) > 0
                        && caps.reach(i, push[0], push[1], Caps.CHAIN - 1, robot) < 1) {
                    blocking = i;
                    return false;
                }
            }
        }
        return true;
    }

    /** The largest fraction of the move (tx, ty) from (px, py) that the caps allow, by bisection. */
    double freeFraction(double px, double py, double tx, double ty, double pc, double ps) {
        double f = 0;
        double hi = 1;
        for (int k = 0; k < BISECT; k++) {
            double mid = (f + hi) * 0.5;
            if (allow(px + mid * tx, py + mid * ty, pc, ps)) {
                f = mid;
            } else {
                hi = mid;
            }
        }
        return f;
    }

    /** Push every cap the robot at this pose overlaps out of its way. */
    void push(double px, double py, double pc, double ps) {
        int parts = pusherCount();
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            for (int part = 0; part < parts; part++) {
                if (overlap(part, px, py, pc, ps, i) > 0) {
                    caps.push(i, push[0], push[1], Caps.CHAIN - 1, robot);
                }
            }
        }
    }

    /**
     * How far part {@code part} of the robot at pose (px, py, pc, ps) overlaps cap i: writes the
     * displacement that would free the cap into {@link #push} and returns its length (≤ 0: no overlap).
     */
    private double overlap(int part, double px, double py, double pc, double ps, int i) {
        double cx = caps.x(i);
        double cy = caps.y(i);
        double qx;
        double qy;
        double radius;
        if (part == 0) {
            qx = px;
            qy = py;
            radius = bodyRadius;
        } else if (part == 3) {
            qx = px + pc * GripperTurret.GRIP_MM;
            qy = py + ps * GripperTurret.GRIP_MM;
            radius = caps.radius(gripper.heldCap());
        } else {
            // A finger: the segment from base to tip at its lateral offset; the nearest point on it.
            double side = part == 1 ? 1 : -1;
            double half = gripper.fingersClosedAndStill()
                    ? (gripper.heldCap() >= 0 ? caps.radius(gripper.heldCap()) : 0) + GripperTurret.FINGER_RADIUS_MM
                    : GripperTurret.OPEN_HALF_GAP_MM;
            double lx = (cx - px) * pc + (cy - py) * ps;
            lx = StrictMath.max(GripperTurret.FINGER_BASE_MM, StrictMath.min(GripperTurret.FINGER_TIP_MM, lx));
            double ly = side * half;
            qx = px + pc * lx - ps * ly;
            qy = py + ps * lx + pc * ly;
            radius = GripperTurret.FINGER_RADIUS_MM;
        }
        double ex = cx - qx;
        double ey = cy - qy;
        double d2 = ex * ex + ey * ey;
        double touch = radius + caps.radius(i);
        if (d2 >= touch * touch) {
            return 0;
        }
        double d = StrictMath.sqrt(d2);
        if (d == 0) {
            // Dead centre: push straight ahead.
            ex = pc;
            ey = ps;
            d = 1;
        }
        double need = touch - d + 1e-9;
        push[0] = ex / d * need;
        push[1] = ey / d * need;
        return need;
    }
}
