package org.kheperasim.sim.host;

import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.api.spi.TruePose;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;

/**
 * The simulated robot behind a controller's API: every call goes through the controller's clock
 * (which charges its simulated time and keeps the lockstep) to the robot's link, so the controller
 * sees what the serial link would have delivered by then.
 *
 * <p>The vision turret is read as robot-link reads it, one exchange per read: the controller waits
 * for the command's characters and the robot's turnaround, the turret gives the image it has at
 * that moment, and the controller waits for the reply's characters (64 numbers: about 60 ms at
 * 38400 baud). A step controller runs on the robot's own processor and reads the turret at once.
 */
final class SimulatedRobotPort implements RobotPort {
    /** The vision turret's id on the extension bus ({@code T,2,...}). */
    private static final String VISION = "T,2,";

    private final SimRobot robot;
    private final PortClock clock;
    private final boolean onBoard;
    /** Loop pauses taken so far ({@link #pauseLoop}): the index of the next one's draw. */
    private long loopPauses;
    /** The robot's largest reading ({@link #maxProximity()}), -1 until first asked. */
    private int contactReading = -1;

    SimulatedRobotPort(SimRobot robot, PortClock clock) {
        this.robot = robot;
        this.clock = clock;
        // A step controller, or any in controller.mode=onboard, runs on the robot's processor: no serial
        // line between it and the turret.
        this.onBoard = clock instanceof StepHost || robot.runsOnBoard();
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
    public void setArmDown(boolean down) {
        clock.enter();
        robot.controls().commandArm(clock.now(), down ? ArmPosition.DOWN : ArmPosition.UP);
        clock.leave();
    }

    @Override
    public boolean armDown() {
        clock.enter();
        boolean v = robot.gripper().armRest() == ArmPosition.DOWN;
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
    public void setFingersClosed(boolean closed) {
        clock.enter();
        robot.controls().commandFingers(clock.now(), closed ? GripperState.CLOSED : GripperState.OPEN);
        clock.leave();
    }

    @Override
    public boolean fingersClosed() {
        clock.enter();
        boolean v = robot.gripper().fingers() == GripperState.CLOSED;
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
    public int[] visionImage() {
        int[] image = exchange('N');
        return image;
    }

    @Override
    public int visionBrightest() {
        return exchange('O')[0];
    }

    @Override
    public int visionDarkest() {
        return exchange('P')[0];
    }

    /**
     * One turret command ({@code T,2,N}, {@code O} or {@code P}) and its reply, at the link's pace.
     *
     * @return the image for {@code N}; the pixel's index, alone, for {@code O} and {@code P}
     */
    private int[] exchange(char command) {
        LinkTiming timing = robot.link();
        if (!onBoard) {
            waitFor(timing.wireNanos(VISION.length() + 2) + timing.turnaroundNanos());
        }
        clock.enter();
        int[] answer = switch (command) {
            case 'N' -> robot.vision().image(clock.now());
            case 'O' -> new int[] {robot.vision().brightest(clock.now())};
            default -> new int[] {robot.vision().darkest(clock.now())};
        };
        clock.leave();
        if (!onBoard) {
            // The reply: "t,2,n" and a comma and the digits of each value, then CR LF.
            int chars = VISION.length() + 1 + 2;
            for (int v : answer) {
                chars += 1 + Integer.toString(v).length();
            }
            waitFor(timing.wireNanos(chars));
        }
        return answer;
    }

    private void waitFor(long nanos) {
        try {
            clock.sleepNanos(nanos);
        } catch (InterruptedException e) {
            // A controller interrupted while its turret answers: the reply still comes.
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public Optional<TruePose> truePose() {
        clock.enter();
        TruePose p = new TruePose(robot.x(), robot.y(), robot.headingDeg(), robot.arenaWidth(), robot.arenaHeight());
        clock.leave();
        return Optional.of(p);
    }

    @Override
    public java.util.Map<String, double[]> parameters() {
        // Free: what the run hands the controller is not the robot's (no time passes, as in a constructor).
        org.kheperasim.api.Parameters given = robot.parameters();
        java.util.Map<String, double[]> byName = new java.util.LinkedHashMap<>();
        for (String name : given.names()) {
            byName.put(name, given.vector(name, null));
        }
        return byName;
    }

    // The robot's description is free too: it is what the robot is, not a reading (no time passes).

    @Override
    public String robotName() {
        return robot.type().name();
    }

    @Override
    public int sensorCount() {
        return robot.type().sensorCount();
    }

    @Override
    public org.kheperasim.api.spi.Mount mount(int index) {
        org.kheperasim.sim.engine.robot.RobotType.Sensor s = robot.type().sensor(index);
        return new org.kheperasim.api.spi.Mount(s.name(), s.xMm(), s.yMm(), s.headingDeg());
    }

    @Override
    public int maxSpeed() {
        return robot.type().drive().maxSpeed();
    }

    @Override
    public double mmPerSecondPerUnit() {
        return robot.type().drive().mmPerSecondPerUnit();
    }

    @Override
    public int maxProximity() {
        // Worked out once: a controller may ask every step, and the type does not change.
        int top = contactReading;
        if (top < 0) {
            top = robot.type().proximity().contactReading();
            contactReading = top;
        }
        return top;
    }

    @Override
    public String option(String key) {
        return Settings.catalogue().containsKey(key) ? robot.settings().raw(key) : null;
    }

    @Override
    public void sleep(long millis) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("sleep of " + millis + " ms: the time must not be negative");
        }
        clock.sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis));
    }

    /** The pause between two doWork() calls of a WSU controller; lengthened under {@code wsu.loopTiming=desktop}. */
    @Override
    public void pauseLoop(long millis) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("pause of " + millis + " ms: the time must not be negative");
        }
        clock.sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis) + robot.loopPauseExtraNanos(loopPauses++));
    }

    @Override
    public void message(String text) {
        clock.enter();
        clock.say(ConsoleLine.Kind.MESSAGE, text);
        clock.leave();
    }
}
