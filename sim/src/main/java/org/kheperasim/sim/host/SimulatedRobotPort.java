package org.kheperasim.sim.host;

import java.util.concurrent.TimeUnit;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.sim.engine.SimRobot;

/**
 * The simulated robot behind a controller's API: every call goes through the controller's clock
 * (which charges its simulated time and keeps the lockstep) to the robot's link, so the controller
 * sees what the serial link would have delivered by then.
 */
final class SimulatedRobotPort implements RobotPort {
    private final SimRobot robot;
    private final PortClock clock;

    SimulatedRobotPort(SimRobot robot, PortClock clock) {
        this.robot = robot;
        this.clock = clock;
    }

    @Override
    public int proximity(int index) {
        clock.enter();
        int v = robot.controls().visibleProximity(clock.now(), index);
        clock.leave();
        return v;
    }

    @Override
    public int ambientLight(int index) {
        clock.enter();
        int v = robot.controls().visibleLight(clock.now(), index);
        clock.leave();
        return v;
    }

    @Override
    public void setSpeeds(int left, int right) {
        clock.enter();
        robot.controls().commandSpeeds(clock.now(), left, right);
        clock.leave();
    }

    @Override
    public int leftSpeed() {
        clock.enter();
        int v = robot.controls().askedLeft();
        clock.leave();
        return v;
    }

    @Override
    public int rightSpeed() {
        clock.enter();
        int v = robot.controls().askedRight();
        clock.leave();
        return v;
    }

    @Override
    public int leftPosition() {
        clock.enter();
        int v = robot.controls().visibleEncoderLeft(clock.now());
        clock.leave();
        return v;
    }

    @Override
    public int rightPosition() {
        clock.enter();
        int v = robot.controls().visibleEncoderRight(clock.now());
        clock.leave();
        return v;
    }

    @Override
    public void setPositions(int left, int right) {
        clock.enter();
        robot.controls().commandPositions(clock.now(), left, right);
        clock.leave();
    }

    @Override
    public void setArm(ArmPosition position) {
        clock.enter();
        robot.controls().commandArm(clock.now(), position);
        clock.leave();
    }

    @Override
    public ArmPosition armPosition() {
        clock.enter();
        ArmPosition v = robot.gripper().armRest();
        clock.leave();
        return v;
    }

    @Override
    public boolean armMoving() {
        clock.enter();
        boolean v = robot.gripper().armMoving();
        clock.leave();
        return v;
    }

    @Override
    public void setFingers(GripperState fingers) {
        clock.enter();
        robot.controls().commandFingers(clock.now(), fingers);
        clock.leave();
    }

    @Override
    public GripperState fingers() {
        clock.enter();
        GripperState v = robot.gripper().fingers();
        clock.leave();
        return v;
    }

    @Override
    public boolean objectPresent() {
        clock.enter();
        boolean v = robot.gripper().objectPresent();
        clock.leave();
        return v;
    }

    @Override
    public int resistivity() {
        clock.enter();
        int v = robot.gripper().resistivity();
        clock.leave();
        return v;
    }

    @Override
    public void sleep(long millis) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("sleep of " + millis + " ms: the time must not be negative");
        }
        clock.sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis));
    }

    @Override
    public void message(String text) {
        clock.enter();
        clock.say(ConsoleLine.Kind.MESSAGE, text);
        clock.leave();
    }
}
