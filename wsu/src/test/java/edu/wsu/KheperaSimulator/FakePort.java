package edu.wsu.KheperaSimulator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.spi.Mount;
import org.kheperasim.api.spi.RobotPort;

/** A robot that lives in the tests: it records what it is told and answers what it is set to. */
class FakePort implements RobotPort {
    final int[] proximity = new int[8];
    final int[] light = {500, 500, 500, 500, 500, 500, 500, 500};
    final List<String> speeds = Collections.synchronizedList(new ArrayList<>());
    final List<Long> sleeps = Collections.synchronizedList(new ArrayList<>());
    final List<String> messages = Collections.synchronizedList(new ArrayList<>());
    volatile int left;
    volatile int right;
    volatile int leftPosition;
    volatile int rightPosition;
    volatile ArmPosition arm = ArmPosition.UP;
    volatile GripperState fingers = GripperState.OPEN;
    volatile boolean object;
    volatile int resistivity;
    /** When set, each sleep also parks the thread 1 ms of real time (for loops the test stops). */
    volatile boolean sleepsTakeRealTime;
    /** What the vision turret sees: 64 grey levels. */
    volatile int[] image = new int[64];
    /** Where the simulator has the robot, or null for a real robot (odometry). */
    volatile org.kheperasim.api.spi.TruePose truth;
    /** The backend's options (wsu.positionUnits). */
    final java.util.Map<String, String> options = new java.util.concurrent.ConcurrentHashMap<>();

    @Override
    public int proximity(int index) {
        return proximity[index];
    }

    @Override
    public int ambientLight(int index) {
        return light[index];
    }

    @Override
    public void setSpeeds(int l, int r) {
        left = l;
        right = r;
        speeds.add(l + "," + r);
    }

    @Override
    public int leftSpeed() {
        return left;
    }

    @Override
    public int rightSpeed() {
        return right;
    }

    @Override
    public int leftPosition() {
        return leftPosition;
    }

    @Override
    public int rightPosition() {
        return rightPosition;
    }

    @Override
    public void setPositions(int l, int r) {
        leftPosition = l;
        rightPosition = r;
    }

    @Override
    public void setArmDown(boolean down) {
        arm = down ? ArmPosition.DOWN : ArmPosition.UP;
    }

    @Override
    public boolean armDown() {
        return arm == ArmPosition.DOWN;
    }

    @Override
    public boolean armMoving() {
        return false;
    }

    @Override
    public void setFingersClosed(boolean closed) {
        fingers = closed ? GripperState.CLOSED : GripperState.OPEN;
    }

    @Override
    public boolean fingersClosed() {
        return fingers == GripperState.CLOSED;
    }

    @Override
    public boolean objectPresent() {
        return object;
    }

    @Override
    public int resistivity() {
        return resistivity;
    }

    @Override
    public void sleep(long millis) throws InterruptedException {
        sleeps.add(millis);
        if (sleepsTakeRealTime) {
            Thread.sleep(1);
        }
    }

    @Override
    public void message(String text) {
        messages.add(text);
    }

    @Override
    public int[] visionImage() {
        return image.clone();
    }

    @Override
    public int visionBrightest() {
        int[] img = image;
        int best = 0;
        for (int i = 1; i < img.length; i++) {
            best = img[i] > img[best] ? i : best;
        }
        return best;
    }

    @Override
    public int visionDarkest() {
        int[] img = image;
        int best = 0;
        for (int i = 1; i < img.length; i++) {
            best = img[i] < img[best] ? i : best;
        }
        return best;
    }

    @Override
    public java.util.Optional<org.kheperasim.api.spi.TruePose> truePose() {
        return java.util.Optional.ofNullable(truth);
    }

    @Override
    public String option(String key) {
        return options.get(key);
    }

    /** @return the last speed command, "left,right", or "" */
    String lastSpeeds() {
        synchronized (speeds) {
            return speeds.isEmpty() ? "" : speeds.get(speeds.size() - 1);
        }
    }

    /** @return the Khepera's sensor poses (the student API's {@code IrSensor}) */
    @Override
    public Mount mount(int index) {
        IrSensor s = IrSensor.of(index);
        return new Mount(s.name(), s.xMm(), s.yMm(), s.headingDeg());
    }
}
