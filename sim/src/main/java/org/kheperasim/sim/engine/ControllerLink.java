package org.kheperasim.sim.engine;

import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;

/**
 * What a controller does to its simulated robot and reads from it, through the simulated serial
 * link: commands that act when their characters and the robot's turnaround have passed, and the
 * values the poll cycle has delivered by the controller's time (see {@link RobotLink}).
 */
public final class ControllerLink {
    private final SimRobot robot;
    private final RobotLink link;

    ControllerLink(SimRobot robot, RobotLink link) {
        this.robot = robot;
        this.link = link;
    }

    /** A controller asks for wheel speeds at simulated time {@code now}, units; they act after the wire time. */
    public void commandSpeeds(long now, int left, int right) {
        link.commandSpeeds(now, left, right);
        robot.commandQueued();
    }

    /** A controller sets the position counters ({@code G}), pulses. */
    public void commandPositions(long now, int left, int right) {
        link.commandPositions(now, left, right);
        robot.commandQueued();
    }

    /** A controller moves the arm up or down ({@code T,1,E,pos}). */
    public void commandArm(long now, ArmPosition position) {
        commandArm(now, position == ArmPosition.DOWN ? GripperTurret.ARM_DOWN : GripperTurret.ARM_UP);
    }

    /** A controller moves the arm to a position, 0..255, larger = lower. */
    public void commandArm(long now, int position) {
        link.commandArm(now, position);
        robot.commandQueued();
    }

    /** A controller opens or closes the fingers ({@code T,1,D,0|1}). */
    public void commandFingers(long now, GripperState state) {
        link.commandFingers(now, state == GripperState.CLOSED);
        robot.commandQueued();
    }

    /** @param i sensor index @return the proximity value a controller sees at the time the robot has been moved to */
    public int visibleProximity(int i) {
        return link.visibleProximity(robot.movedTo(), i);
    }

    /** @param i sensor index @return the light value a controller sees at the time the robot has been moved to */
    public int visibleLight(int i) {
        return link.visibleLight(robot.movedTo(), i);
    }

    /** @param now the controller's simulated time, ns @param i sensor index @return the proximity value it sees */
    public int visibleProximity(long now, int i) {
        return link.visibleProximity(now, i);
    }

    /** @param now the controller's simulated time, ns @param i sensor index @return the light value it sees */
    public int visibleLight(long now, int i) {
        return link.visibleLight(now, i);
    }

    /** @param now the controller's simulated time, ns @return the left position counter it sees, pulses */
    public int visibleEncoderLeft(long now) {
        return link.visibleCounterLeft(now);
    }

    /** @param now the controller's simulated time, ns @return the right position counter it sees, pulses */
    public int visibleEncoderRight(long now) {
        return link.visibleCounterRight(now);
    }

    /** @return the left speed the controller last asked for, units */
    public int askedLeft() {
        return link.askedLeft();
    }

    /** @return the right speed the controller last asked for, units */
    public int askedRight() {
        return link.askedRight();
    }
}
