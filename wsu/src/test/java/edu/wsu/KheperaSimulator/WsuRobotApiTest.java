package edu.wsu.KheperaSimulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;

/** The robot as a WSU controller sees it: speeds, sensors, gripper, wheel positions. */
class WsuRobotApiTest {
    private final FakePort port = new FakePort();
    private final Probe robot = Probe.on(port);

    @Test
    void everyWsuSpeedIsTheSameNumberOfKheperaSpeedUnits() {
        for (int s = -9; s <= 9; s++) {
            robot.setMotorSpeeds(s, -s);
            assertEquals(s + "," + -s, port.lastSpeeds(), "WSU speed " + s);
        }
        assertEquals(1, WsuUnits.KHEPERA_SPEED_PER_WSU_SPEED);
        assertEquals(9, WsuUnits.toKheperaSpeed(9));
    }

    @Test
    void aSpeedOutsideMinusNineToNineIsIgnoredAndThatWheelKeepsItsSpeed() {
        robot.setMotorSpeeds(3, 4);
        robot.setMotorSpeeds(10, -2);
        assertEquals("3,-2", port.lastSpeeds(), "left kept 3");
        robot.setMotorSpeeds(-5, Integer.MAX_VALUE);
        assertEquals("-5,-2", port.lastSpeeds(), "right kept -2");
        int sent = port.speeds.size();
        robot.setMotorSpeeds(-10, 12);
        robot.setMotorSpeeds(Integer.MIN_VALUE, 100);
        robot.setLeftMotorSpeed(-10);
        robot.setRightMotorSpeed(10);
        assertEquals(sent, port.speeds.size(), "nothing to send when every value is out of range");
        robot.setLeftMotorSpeed(9);
        assertEquals("9,-2", port.lastSpeeds());
        robot.setRightMotorSpeed(-9);
        assertEquals("9,-9", port.lastSpeeds());
    }

    @Test
    void sensorsPassThroughInTheRobotsIndexOrder() {
        for (int i = 0; i < 8; i++) {
            port.proximity[i] = 100 + i;
            port.light[i] = 400 - i;
        }
        for (int i = 0; i < 8; i++) {
            assertEquals(100 + i, robot.getDistanceValue(i));
            assertEquals(400 - i, robot.getLightValue(i));
        }
    }

    @Test
    void aSensorThatDoesNotExistIsAnException() {
        for (int i : new int[] {-1, 8, 100}) {
            ArrayIndexOutOfBoundsException e = assertThrows(ArrayIndexOutOfBoundsException.class,
                    () -> robot.getDistanceValue(i));
            assertTrue(e.getMessage().contains("sensor " + i) && e.getMessage().contains("0..7"), e.getMessage());
            assertThrows(ArrayIndexOutOfBoundsException.class, () -> robot.getLightValue(i));
        }
    }

    @Test
    void theGripperStartsUpAndOpenAndTakesOnlyItsOwnStates() {
        assertEquals(KSGripperStates.ARM_UP, robot.getArmState());
        assertEquals(KSGripperStates.GRIP_OPEN, robot.getGripperState());

        robot.setArmState(KSGripperStates.ARM_DOWN);
        assertEquals(ArmPosition.DOWN, port.arm);
        assertEquals(KSGripperStates.ARM_DOWN, robot.getArmState());
        robot.setArmState(KSGripperStates.GRIP_OPEN); // a finger state is no arm state: ignored
        robot.setArmState(0);
        assertEquals(ArmPosition.DOWN, port.arm);

        robot.setGripperState(KSGripperStates.GRIP_CLOSED);
        assertEquals(GripperState.CLOSED, port.fingers);
        assertEquals(KSGripperStates.GRIP_CLOSED, robot.getGripperState());
        robot.setGripperState(KSGripperStates.ARM_UP);
        robot.setGripperState(-1);
        assertEquals(GripperState.CLOSED, port.fingers);

        robot.setArmState(KSGripperStates.ARM_UP);
        robot.setGripperState(KSGripperStates.GRIP_OPEN);
        assertEquals(ArmPosition.UP, port.arm);
        assertEquals(GripperState.OPEN, port.fingers);
    }

    @Test
    void anObjectIsHeldWhenTheClosedFingersBreakTheBarrier() {
        assertFalse(robot.isObjectPresent());
        assertFalse(robot.isObjectHeld());
        port.object = true;
        assertTrue(robot.isObjectPresent());
        assertFalse(robot.isObjectHeld(), "present between open fingers, not held");
        port.fingers = GripperState.CLOSED;
        port.resistivity = 120;
        assertTrue(robot.isObjectHeld());
        assertEquals(120, robot.getResistivity());
        port.object = false;
        assertFalse(robot.isObjectHeld(), "closed on nothing");
    }

    @Test
    void wheelPositionsAreLongPulsesFromZeroAtTheRunStartAndDoNotWrap() {
        port.leftPosition = 1000;
        port.rightPosition = Integer.MAX_VALUE - 10;
        robot.robot().startRun();
        assertEquals(0L, robot.getLeftWheelPosition());
        assertEquals(0L, robot.getRightWheelPosition());
        port.leftPosition = 1500;
        port.rightPosition = Integer.MAX_VALUE;
        assertEquals(500L, robot.getLeftWheelPosition());
        assertEquals(10L, robot.getRightWheelPosition());
        port.rightPosition = Integer.MIN_VALUE + 9; // the robot's 32-bit counter wrapped
        assertEquals(20L, robot.getRightWheelPosition());
        port.leftPosition = 900;
        assertEquals(-100L, robot.getLeftWheelPosition(), "driving backwards counts down");
    }

    @Test
    void sleepIsRobotTimeAndSwallowsInterruptions() {
        robot.sleep(35);
        robot.sleep(0);
        robot.sleep(-5);
        assertEquals(List.of(35L), port.sleeps, "nothing to sleep for 0 or less");
        FakePort interrupting = new FakePort() {
            @Override
            public void sleep(long millis) throws InterruptedException {
                throw new InterruptedException();
            }
        };
        Probe.on(interrupting).sleep(10); // swallowed, as in the original
    }

    @Test
    void aControllerUsedBeforeTheSimulatorConnectsItSaysSo() {
        Probe unconnected = new Probe();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> unconnected.setMotorSpeeds(1, 1));
        assertTrue(e.getMessage().contains("Probe") && e.getMessage().contains("doWork()"), e.getMessage());
    }

    @Test
    void aStateMadeWithItsPublicConstructorIsConnectedToNothing() {
        CurrentRobotState detached = new CurrentRobotState();
        detached.setMotorSpeeds(4, 5);
        detached.setLeftMotorSpeed(2);
        assertEquals(2, detached.leftSpeed());
        assertEquals(5, detached.rightSpeed());
        assertEquals(0L, detached.getLeftPosition());
        assertEquals(0L, detached.getRightPosition());
    }

    @Test
    void thePublicStateDrivesTheSameRobot() {
        CurrentRobotState state = new CurrentRobotState(port);
        state.setMotorSpeeds(2, 3);
        state.setRightMotorSpeed(-4);
        assertEquals("2,-4", port.lastSpeeds());
        port.leftPosition = 42;
        assertEquals(0L, state.getLeftPosition(), "without a marked run start, the first read is the start");
        port.leftPosition = 50;
        assertEquals(8L, state.getLeftPosition());
    }
}
