package org.kheperasim.sim.engine;

import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.link.timing.PollStep;
import org.kheperasim.sim.engine.link.RobotLink;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.view.DriverRecorder;

/**
 * What a controller does to its simulated robot and reads from it. Tethered (the default for a
 * thread-style controller), through the simulated serial link: commands act when their characters
 * and the robot's turnaround have passed, and it sees the values the poll cycle has delivered by
 * its time (see {@link RobotLink}). On-board (the default for a step controller), on the robot's
 * own processor: it reads the latest 20 ms scan and the counters, and its commands act at once
 * (see {@link OnBoardLink}).
 */
public final class ControllerLink {
    private final SimRobot robot;
    private final RobotLink link;
    /** The controller runs on the robot, or null: through the link. */
    private OnBoardLink onBoard;
    /** Hears every command that reaches the link (a command log), or null. */
    private DriverRecorder recorder;

    ControllerLink(SimRobot robot, RobotLink link) {
        this.robot = robot;
        this.link = link;
    }

    void record(DriverRecorder recorder) {
        this.recorder = recorder;
    }

    /** @param board the controller runs on the robot from now on */
    void onBoard(OnBoardLink board) {
        this.onBoard = board;
    }

    /** @return true when the controller runs on the robot (on-board), false when through the serial link */
    public boolean isOnBoard() {
        return onBoard != null;
    }

    /** A controller asks for wheel speeds at simulated time {@code now}, units; they act after the wire time. */
    public void commandSpeeds(long now, int left, int right) {
        if (onBoard != null) {
            if (recorder != null && onBoard.speedsWouldChange(left, right)) {
                recorder.speeds(robot.id(), now, left, right);
            }
            onBoard.commandSpeeds(left, right);
            return;
        }
        // A busy loop asks for the same speeds tens of thousands of times a second: only calls that change the
        // link are told, which replays the same (the others leave every field of the link as it was).
        if (recorder != null && link.speedsWouldChange(now, left, right)) {
            recorder.speeds(robot.id(), now, left, right);
        }
        link.commandSpeeds(now, left, right);
        robot.commandQueued();
    }

    /** A controller sets the position counters ({@code G}), pulses. */
    public void commandPositions(long now, int left, int right) {
        if (recorder != null) {
            recorder.positions(robot.id(), now, left, right);
        }
        if (onBoard != null) {
            onBoard.commandPositions(left, right);
            return;
        }
        link.commandPositions(now, left, right);
        robot.commandQueued();
    }

    /** A controller moves the arm up or down ({@code T,1,E,pos}). */
    public void commandArm(long now, ArmPosition position) {
        commandArm(now, position == ArmPosition.DOWN ? GripperTurret.ARM_DOWN : GripperTurret.ARM_UP);
    }

    /** A controller moves the arm to a position, 0..255, larger = lower. */
    public void commandArm(long now, int position) {
        if (recorder != null) {
            recorder.arm(robot.id(), now, position);
        }
        if (onBoard != null) {
            onBoard.commandArm(robot.movedTo(), position);
            return;
        }
        link.commandArm(now, position);
        robot.commandQueued();
    }

    /** A controller opens or closes the fingers ({@code T,1,D,0|1}). */
    public void commandFingers(long now, GripperState state) {
        if (recorder != null) {
            recorder.fingers(robot.id(), now, state == GripperState.CLOSED);
        }
        if (onBoard != null) {
            onBoard.commandFingers(robot.movedTo(), state == GripperState.CLOSED);
            return;
        }
        link.commandFingers(now, state == GripperState.CLOSED);
        robot.commandQueued();
    }

    /** @param i sensor index @return the proximity value a controller sees at the time the robot has been moved to */
    public int visibleProximity(int i) {
        return onBoard != null ? onBoard.proximity(robot.movedTo(), i) : link.visibleProximity(robot.movedTo(), i);
    }

    /** @param i sensor index @return the light value a controller sees at the time the robot has been moved to */
    public int visibleLight(int i) {
        return onBoard != null ? onBoard.light(robot.movedTo(), i) : link.visibleLight(robot.movedTo(), i);
    }

    /** @param now the controller's simulated time, ns @param i sensor index @return the proximity value it sees */
    public int visibleProximity(long now, int i) {
        if (onBoard != null) {
            return onBoard.proximity(now, i);
        }
        read(PollStep.PROXIMITY, now);
        return link.visibleProximity(now, i);
    }

    /** @param now the controller's simulated time, ns @param i sensor index @return the light value it sees */
    public int visibleLight(long now, int i) {
        if (onBoard != null) {
            return onBoard.light(now, i);
        }
        read(PollStep.LIGHT, now);
        return link.visibleLight(now, i);
    }

    /** @param now the controller's simulated time, ns @return the left position counter it sees, pulses */
    public int visibleEncoderLeft(long now) {
        if (onBoard != null) {
            return onBoard.counterLeft();
        }
        read(PollStep.ENCODERS, now);
        return link.visibleCounterLeft(now);
    }

    /** @param now the controller's simulated time, ns @return the right position counter it sees, pulses */
    public int visibleEncoderRight(long now) {
        if (onBoard != null) {
            return onBoard.counterRight();
        }
        read(PollStep.ENCODERS, now);
        return link.visibleCounterRight(now);
    }

    /** A read that brings a reply in early is told: it changes what the engine's tick shows from then on. */
    private void read(PollStep step, long now) {
        if (recorder != null && link.readDelivers(step, now)) {
            recorder.delivered(robot.id(), now, step);
        }
    }

    /** @return the poll cycles the link has run so far (proximity replies taken), for measuring its rate */
    public long pollCycles() {
        return link.proximityReplies();
    }

    /** @return the left speed the controller last asked for, units */
    public int askedLeft() {
        return onBoard != null ? onBoard.askedLeft() : link.askedLeft();
    }

    /** @return the right speed the controller last asked for, units */
    public int askedRight() {
        return onBoard != null ? onBoard.askedRight() : link.askedRight();
    }
}
