package org.kheperasim.sim.engine;

import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.sensing.Scans;

/**
 * A controller running on the robot's own processor (on-board): no serial link between it and the
 * robot. It reads the robot's latest 20 ms {@link Scans scan} and the counters as they are, and
 * its commands act at once, from the tick it gives them in. Swarms and evolutionary robotics run
 * the Khepera this way (a program cross-compiled into its flash), as Enki, ARGoS and Webots step
 * their controllers.
 */
final class OnBoardLink {
    private final SimRobot robot;
    private final DriveBody body;
    private final GripperModel gripper;
    private final Scans scans;
    private int askedLeft;
    private int askedRight;

    OnBoardLink(SimRobot robot, DriveBody body, GripperModel gripper, Scans scans) {
        this.robot = robot;
        this.body = body;
        this.gripper = gripper;
        this.scans = scans;
    }

    /** @return true when {@code left, right} differ from the speeds set last */
    boolean speedsWouldChange(int left, int right) {
        return left != askedLeft || right != askedRight;
    }

    void commandSpeeds(int left, int right) {
        askedLeft = left;
        askedRight = right;
        body.wheels().setSpeeds(left, right);
    }

    void commandPositions(int left, int right) {
        body.setCounters(left, right);
    }

    void commandArm(long now, int position) {
        gripper.moveArm(now, StrictMath.max(0, StrictMath.min(255, position)));
    }

    void commandFingers(long now, boolean closed) {
        gripper.moveFingers(now, closed ? GripperState.CLOSED : GripperState.OPEN);
    }

    int proximity(long now, int i) {
        return scans.proximityOf(now, i);
    }

    int light(long now, int i) {
        return scans.lightOf(now, i);
    }

    int counterLeft() {
        return DriveBody.pulses(body.encoderLeftExact());
    }

    int counterRight() {
        return DriveBody.pulses(body.encoderRightExact());
    }

    /** The values of the latest scan, for a snapshot: what the controller reads now. */
    void copyLatest(int[] prox, int[] light) {
        scans.latest(prox, light);
    }

    void reset() {
        askedLeft = 0;
        askedRight = 0;
    }

    int askedLeft() {
        return askedLeft;
    }

    int askedRight() {
        return askedRight;
    }
}
