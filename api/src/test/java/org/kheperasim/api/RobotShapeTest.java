package org.kheperasim.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.kheperasim.api.spi.Mount;
import org.kheperasim.api.spi.RobotPort;

/** The student API follows the robot: its sensors (count, names, mounts) and its speed units. */
class RobotShapeTest {

    /** A port whose robot has three sensors and a speed limit of 1000 units of 0.1288 mm/s. */
    private static class TriPort implements RobotPort {
        int left;
        int right;

        @Override public String robotName() { return "tri"; }
        @Override public int sensorCount() { return 3; }
        @Override public Mount mount(int i) { return new Mount("s" + i, 20, 10 - 10 * i, 45 - 45 * i); }
        @Override public int maxSpeed() { return 1000; }
        @Override public double mmPerSecondPerUnit() { return 0.1288; }
        @Override public int proximity(int index) { return 100 + index; }
        @Override public int ambientLight(int index) { return 400 + index; }
        @Override public void setSpeeds(int l, int r) { left = l; right = r; }
        @Override public int leftSpeed() { return left; }
        @Override public int rightSpeed() { return right; }
        @Override public int leftPosition() { return 0; }
        @Override public int rightPosition() { return 0; }
        @Override public void setPositions(int l, int r) { }
        @Override public void setArmDown(boolean down) { }
        @Override public boolean armDown() { return false; }
        @Override public boolean armMoving() { return false; }
        @Override public void setFingersClosed(boolean closed) { }
        @Override public boolean fingersClosed() { return false; }
        @Override public boolean objectPresent() { return false; }
        @Override public int resistivity() { return 0; }
        @Override public void sleep(long millis) { }
        @Override public void message(String text) { }
    }

    @Test
    void aControllerSeesTheSensorsItsRobotHas() {
        CurrentRobotState state = new CurrentRobotState(new TriPort());
        Sensor[] sensors = state.getSensorValues();
        assertEquals(3, sensors.length);
        assertEquals("s2", sensors[2].getMount().name());
        assertEquals(-45.0, sensors[2].getMount().headingDeg());
        assertEquals(102, sensors[2].getDistValue());
        assertSame(sensors[1], state.getSensor(IrSensor.LEFT_45));
        assertEquals("tri", state.getRobotName());
    }

    @Test
    void aSensorTheRobotLacksIsRefusedNamingTheRobot() {
        CurrentRobotState state = new CurrentRobotState(new TriPort());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> state.getSensor(IrSensor.RIGHT_90));
        assertEquals("sensor 5 (RIGHT_90) does not exist: this robot (tri) has 3 sensors, 0..2; the controller was"
                + " written for another robot (see docs/robot-files.md)", e.getMessage());
    }

    @Test
    void speedsAreInTheRobotsUnitsUpToItsLimit() {
        TriPort port = new TriPort();
        Motor m = new CurrentRobotState(port).getMotorState();
        m.setMotorSpeeds(1000, -600);
        assertEquals(1000, port.left);
        assertEquals(1000, m.getMaxSpeed());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setMotorSpeeds(1001, 0));
        assertEquals("setMotorSpeeds(1001, 0): each speed must lie in -1000..1000 speed units (1 unit is about"
                + " 0.1288 mm/s); clamp the value before calling", e.getMessage());
    }

    @Test
    void aKheperaPortKeepsTheKheperasShapeAndMessage() {
        RobotPort khepera = new TriPort() {
            @Override public String robotName() { return "khepera1"; }
            @Override public int sensorCount() { return IrSensor.COUNT; }
            @Override public Mount mount(int i) {
                IrSensor s = IrSensor.of(i);
                return new Mount(s.name(), s.xMm(), s.yMm(), s.headingDeg());
            }
            @Override public int maxSpeed() { return Motor.MAX_SPEED; }
            @Override public double mmPerSecondPerUnit() { return 8; }
        };
        CurrentRobotState state = new CurrentRobotState(khepera);
        assertEquals(8, state.getSensorValues().length);
        assertEquals(IrSensor.BACK_LEFT, state.getSensorValues()[7].getPosition());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> state.getMotorState().setMotorSpeeds(128, 0));
        assertEquals("setMotorSpeeds(128, 0): each speed must lie in -127..127 speed units (1 unit is about 8 mm/s);"
                + " clamp the value before calling", e.getMessage());
    }
}
