package org.kheperasim.sim.engine.body;

import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.RayHit;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.space.Caps;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.GripperView;

/**
 * The gripper turret of one robot: the arm travels toward its target at a fixed rate, the fingers
 * take a fixed time to open or close, a cap between them when they close is held and carried, and
 * the optical barrier between the fingers sees what breaks it. The arm's position is a closed form
 * of the time since its target was set, so it is the same however the engine steps.
 */
public final class GripperModel {
    private final int robotId;
    private final Caps caps;
    private final OccupancyGrid grid;
    private final DriveBody body;
    private final double armStepPerTick;
    private final long fingerNanos;
    private final int capResistivity;
    private final RayHit hit = new RayHit();

    private double armFrom = GripperTurret.ARM_UP;
    private long armSince;
    private double armPos = GripperTurret.ARM_UP;
    private int armTarget = GripperTurret.ARM_UP;
    private ArmPosition armRest = ArmPosition.UP;
    private GripperState fingers = GripperState.OPEN;
    private GripperState fingerTarget = GripperState.OPEN;
    private long fingersDoneAt = Long.MAX_VALUE;
    private int heldCap = -1;

    public GripperModel(int robotId, World world, DriveBody body, RobotModel.Gripper model) {
        this.robotId = robotId;
        this.caps = world.capSet();
        this.grid = world.grid();
        this.body = body;
        this.armStepPerTick = (GripperTurret.ARM_DOWN - GripperTurret.ARM_UP)
                / ((double) model.armTravelNanos() / Ticks.NANOS);
        this.fingerNanos = model.fingerNanos();
        this.capResistivity = model.capResistivity();
    }

    /**
     * Send the arm toward a position from time {@code now} on.
     *
     * @param now simulated time, ns
     * @param position 0..255, larger = lower (see {@link GripperTurret})
     */
    public void moveArm(long now, int position) {
        armFrom = armPos;
        armSince = now;
        armTarget = StrictMath.max(0, StrictMath.min(255, position));
    }

    /** Start the fingers toward {@code target} at {@code now}; opening drops a held cap at once. */
    public void moveFingers(long now, GripperState target) {
        if (target == fingerTarget) {
            return;
        }
        fingerTarget = target;
        fingersDoneAt = now + fingerNanos;
        if (target == GripperState.OPEN && heldCap >= 0) {
            double gx = body.x() + body.cos() * GripperTurret.GRIP_MM;
            double gy = body.y() + body.sin() * GripperTurret.GRIP_MM;
            caps.drop(heldCap, gx, gy, body.x(), body.y(), body.radius());
            heldCap = -1;
        }
    }

    /** @return true while the arm or the fingers move (the engine then steps tick by tick) */
    public boolean busy() {
        return armPos != armTarget || fingersDoneAt != Long.MAX_VALUE;
    }

    /** The robot has moved to the end of a tick at {@code endNanos}: the turret follows. */
    public void moved(long endNanos) {
        if (armPos != armTarget) {
            double travelled = armStepPerTick * ((endNanos - armSince) / Ticks.NANOS);
            double d = armTarget - armFrom;
            armPos = travelled >= StrictMath.abs(d) ? armTarget : armFrom + StrictMath.signum(d) * travelled;
            if (armPos == armTarget) {
                armRest = armTarget >= GripperTurret.ARM_LOW ? ArmPosition.DOWN : ArmPosition.UP;
            }
        }
        if (fingersDoneAt <= endNanos) {
            fingersDoneAt = Long.MAX_VALUE;
            fingers = fingerTarget;
            if (fingers == GripperState.CLOSED && heldCap < 0 && armLow()) {
                int cap = capBetweenFingers();
                if (cap >= 0) {
                    caps.hold(cap, robotId);
                    heldCap = cap;
                }
            }
        }
        if (heldCap >= 0) {
            caps.carry(heldCap, body.x() + body.cos() * GripperTurret.GRIP_MM,
                    body.y() + body.sin() * GripperTurret.GRIP_MM);
        }
    }

    /** @return the cap on the floor whose centre lies between the open fingers, nearest the grip point; or -1 */
    private int capBetweenFingers() {
        int best = -1;
        double bestScore = Double.POSITIVE_INFINITY;
        double inner = GripperTurret.OPEN_HALF_GAP_MM - GripperTurret.FINGER_RADIUS_MM;
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            double dx = caps.x(i) - body.x();
            double dy = caps.y(i) - body.y();
            double lx = dx * body.cos() + dy * body.sin();
            double ly = dy * body.cos() - dx * body.sin();
            if (lx >= body.radius() - 1 && lx <= GripperTurret.FINGER_TIP_MM && StrictMath.abs(ly) < inner) {
                double score = StrictMath.abs(lx - GripperTurret.GRIP_MM) + StrictMath.abs(ly);
                if (score < bestScore) {
                    bestScore = score;
                    best = i;
                }
            }
        }
        return best;
    }

    /** The arena was edited: a held cap that no longer exists is let go. */
    public void arenaEdited() {
        if (heldCap >= caps.count()) {
            heldCap = -1;
        }
    }

    /** @return true when the arm is low enough for the fingers to reach the caps */
    public boolean armLow() {
        return armPos >= GripperTurret.ARM_LOW;
    }

    /** @return true when the fingers are closed and not moving */
    boolean fingersClosedAndStill() {
        return fingers == GripperState.CLOSED && fingersDoneAt == Long.MAX_VALUE;
    }

    /** @return where the arm last came to rest (while moving: the position it left) */
    ArmPosition armRest() {
        return armRest;
    }

    /** @return the arm's position now, in the turret's 8-bit units */
    int armPosition() {
        return (int) StrictMath.rint(armPos);
    }

    /** @return true while the arm travels */
    boolean armMoving() {
        return armPos != armTarget;
    }

    /** @return the state the fingers last reached (while moving: the state they left) */
    GripperState fingers() {
        return fingers;
    }

    /** @return the id of the cap the fingers hold, or -1 */
    public int heldCap() {
        return heldCap;
    }

    /**
     * The optical barrier between the fingers: broken by a held cap, or, with the arm low, by
     * anything on the floor crossing the line between the fingers.
     */
    boolean objectPresent() {
        if (heldCap >= 0) {
            return true;
        }
        if (!armLow()) {
            return false;
        }
        double half = GripperTurret.OPEN_HALF_GAP_MM - GripperTurret.FINGER_RADIUS_MM;
        double c = body.cos();
        double s = body.sin();
        double ox = body.x() + c * GripperTurret.GRIP_MM - s * half;
        double oy = body.y() + s * GripperTurret.GRIP_MM + c * half;
        return grid.castRay(ox, oy, s, -c, 2 * half, hit) != Double.POSITIVE_INFINITY;
    }

    /** @return resistivity of what the fingers hold, 0..255; 0 when they hold nothing */
    int resistivity() {
        return heldCap >= 0 ? capResistivity : 0;
    }

    /** @return the turret's state now */
    GripperView view() {
        return new GripperView(armPosition(), armMoving(), fingers, objectPresent(), resistivity(), heldCap);
    }
}
