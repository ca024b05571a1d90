package org.kheperasim.link.robot;

import org.kheperasim.api.spi.RobotPort;

/** A {@link RobotPort} that passes every call on; subclasses change one or two. */
class DelegatingPort implements RobotPort {
    private final RobotPort target;

    DelegatingPort(RobotPort target) {
        this.target = target;
    }

    @Override public int proximity(int index) { return target.proximity(index); }
    @Override public int ambientLight(int index) { return target.ambientLight(index); }
    @Override public void setSpeeds(int left, int right) { target.setSpeeds(left, right); }
    @Override public int leftSpeed() { return target.leftSpeed(); }
    @Override public int rightSpeed() { return target.rightSpeed(); }
    @Override public int leftPosition() { return target.leftPosition(); }
    @Override public int rightPosition() { return target.rightPosition(); }
    @Override public void setPositions(int left, int right) { target.setPositions(left, right); }
    @Override public void setArmDown(boolean down) { target.setArmDown(down); }
    @Override public boolean armDown() { return target.armDown(); }
    @Override public boolean armMoving() { return target.armMoving(); }
    @Override public void setFingersClosed(boolean closed) { target.setFingersClosed(closed); }
    @Override public boolean fingersClosed() { return target.fingersClosed(); }
    @Override public boolean objectPresent() { return target.objectPresent(); }
    @Override public int resistivity() { return target.resistivity(); }
    @Override public void sleep(long millis) throws InterruptedException { target.sleep(millis); }
    @Override public void pauseLoop(long millis) throws InterruptedException { target.pauseLoop(millis); }
    @Override public void message(String text) { target.message(text); }
    @Override public int[] visionImage() { return target.visionImage(); }
    @Override public int visionBrightest() { return target.visionBrightest(); }
    @Override public int visionDarkest() { return target.visionDarkest(); }
    @Override public java.util.Optional<org.kheperasim.api.spi.TruePose> truePose() { return target.truePose(); }
    @Override public String option(String key) { return target.option(key); }
    @Override public String robotName() { return target.robotName(); }
    @Override public int sensorCount() { return target.sensorCount(); }
    @Override public org.kheperasim.api.spi.Mount mount(int index) { return target.mount(index); }
    @Override public int maxSpeed() { return target.maxSpeed(); }
    @Override public double mmPerSecondPerUnit() { return target.mmPerSecondPerUnit(); }
    @Override public int maxProximity() { return target.maxProximity(); }
}
