package org.kheperasim.sim.engine;

import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.body.PositionControl;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot as a protocol client drives it directly (the protocol server): each command acts at
 * once, as on the robot when its characters have arrived. Speed, position ({@code C}, {@code J})
 * and PWM modes, the motion status {@code K} reports, sensors read on demand, the counters, the
 * gripper turret and the LEDs. A run with a controller never leaves speed mode.
 */
public final class OnBoardControl {

    /** The robot's three motor modes, as its {@code K} status reports them. */
    public enum MotorMode {
        /** {@code D}: the wheels hold a speed. */
        SPEED(0),
        /** {@code C}: the wheels move to position targets along a trapezoid profile. */
        POSITION(1),
        /** {@code P}: raw PWM. */
        PWM(2);

        private final int code;

        MotorMode(int code) {
            this.code = code;
        }

        /** @return the number {@code K} reports for this mode */
        public int code() {
            return code;
        }
    }

    private final SimRobot robot;
    private final DriveBody body;
    private final GripperModel gripper;
    private final PositionControl left;
    private final PositionControl right;
    /** The motor controller's period, ns, and the speed limit, units: the robot type's. */
    private final long motorPeriod;
    private final int speedLimit;
    private MotorMode mode = MotorMode.SPEED;
    private long nextUpdate = Long.MAX_VALUE;
    private int leds;

    OnBoardControl(SimRobot robot, DriveBody body, GripperModel gripper, RobotType.Drive drive) {
        this.left = new PositionControl(drive);
        this.right = new PositionControl(drive);
        this.motorPeriod = drive.motorPeriodNanos();
        this.speedLimit = drive.maxSpeed();
        this.robot = robot;
        this.body = body;
        this.gripper = gripper;
    }

    /** A protocol client drives the robot itself: the simulated controller's link stops polling. */
    public void servedDirectly() {
        robot.servedDirectly();
    }

    /** Read the eight proximity sensors now, with their noise ({@code N} arrived); 0..1023, higher = nearer. */
    public void readProximity(int[] out) {
        robot.readProximityNow(out);
    }

    /** Read the eight ambient-light sensors now ({@code O} arrived); 0..1023, lower = brighter. */
    public void readLight(int[] out) {
        robot.readLightNow(out);
    }

    /** Set the position counters at once ({@code G} arrived), pulses. */
    public void setCounters(int left, int right) {
        body.setCounters(left, right);
    }

    /** @return the left position counter now, pulses ({@code H}) */
    public int counterLeft() {
        return DriveBody.pulses(body.encoderLeftExact());
    }

    /** @return the right position counter now, pulses */
    public int counterRight() {
        return DriveBody.pulses(body.encoderRightExact());
    }

    /** Move the arm at once ({@code T,1,E,pos} arrived) from simulated time {@code now}; 0..255, larger = lower. */
    public void moveArm(long now, int position) {
        gripper.moveArm(now, position);
    }

    /** Start the fingers at once ({@code T,1,D,0|1} arrived at {@code now}). */
    public void moveFingers(long now, org.kheperasim.api.GripperState state) {
        gripper.moveFingers(now, state);
    }

    /** Leave position and PWM mode (a speed command, or the robot was stopped). */
    void speedMode() {
        leave(MotorMode.SPEED);
    }

    private void leave(MotorMode next) {
        left.cancel();
        right.cancel();
        nextUpdate = Long.MAX_VALUE;
        mode = next;
    }

    /**
     * Set the wheel speeds at once, as the robot does when a {@code D} command has arrived.
     *
     * @param l left speed, units (≈ 8 mm/s), -127..127
     * @param r right speed, units
     */
    public void driveSpeeds(int l, int r) {
        leave(MotorMode.SPEED);
        robot.asked(l, r);
        body.wheels().setSpeeds(l, r);
    }

    /**
     * Raw PWM ({@code P}), approximated: the simulator has no motor model, so a duty of d/255 gives
     * about the robot's top speed times d/255 (the Khepera: 127 units ≈ 1 m/s).
     *
     * @param l left PWM, -255..255
     * @param r right PWM, -255..255
     */
    public void drivePwm(int l, int r) {
        leave(MotorMode.PWM);
        body.wheels().setSpeeds(pwmToSpeed(l, speedLimit), pwmToSpeed(r, speedLimit));
    }

    /** @param pwm -255..255 @param limit the robot's top speed, units @return the speed it gives, units */
    public static int pwmToSpeed(int pwm, int limit) {
        return (int) StrictMath.rint(StrictMath.max(-255, StrictMath.min(255, pwm)) * (double) limit / 255.0);
    }

    /**
     * Move the wheels to absolute counter targets ({@code C,l,r}) along the profile set by
     * {@link #positionProfile}; the move starts at the next tick and is updated every 10 ms.
     *
     * @param l left target, pulses (0.08 mm)
     * @param r right target, pulses
     * @param now simulated time, ns
     */
    public void moveToPositions(long now, int l, int r) {
        left.moveTo(l, body.wheels().speedLeft());
        right.moveTo(r, body.wheels().speedRight());
        mode = MotorMode.POSITION;
        nextUpdate = now;
        robot.positionMoveStarted(now);
    }

    /**
     * The profile of position moves ({@code J,max_l,acc_l,max_r,acc_r}); see {@link PositionControl}.
     *
     * @param maxLeft left maximum speed, units
     * @param accLeft left acceleration, 1/256 unit per 10 ms
     * @param maxRight right maximum speed, units
     * @param accRight right acceleration, 1/256 unit per 10 ms
     */
    public void positionProfile(int maxLeft, int accLeft, int maxRight, int accRight) {
        left.profile(maxLeft, accLeft);
        right.profile(maxRight, accRight);
    }

    /** Update a position move when its 10 ms period has come round; returns when it is next due, ns. */
    long due(long now) {
        if (now >= nextUpdate) {
            nextUpdate = now + motorPeriod;
            body.wheels().setSpeeds(left.update(body.encoderLeftExact()), right.update(body.encoderRightExact()));
        }
        return nextUpdate;
    }

    /**
     * The motion status as {@code K} reports it: per wheel (left, then right) whether it is on
     * target (1/0), its mode ({@link MotorMode#code()}), and its error: in position mode the
     * distance to the target in pulses, in speed and PWM mode 0.
     *
     * @return {Tl, Ml, El, Tr, Mr, Er}
     */
    public int[] motionStatus() {
        int[] k = new int[6];
        status(k, 0, left, body.encoderLeftExact());
        status(k, 3, right, body.encoderRightExact());
        return k;
    }

    private void status(int[] k, int at, PositionControl control, double position) {
        k[at + 1] = mode.code();
        if (mode == MotorMode.POSITION) {
            k[at] = control.onTarget(position) ? 1 : 0;
            k[at + 2] = (int) StrictMath.rint(control.target() - position);
        } else {
            k[at] = 1;
            k[at + 2] = 0;
        }
    }

    /** @return the motor mode now */
    public MotorMode motorMode() {
        return mode;
    }

    /**
     * An LED command ({@code L,n,action}).
     *
     * @param led 0 lateral, 1 front
     * @param action 0 off, 1 on, 2 toggle
     */
    public void setLed(int led, int action) {
        int bit = 1 << led;
        leds = switch (action) {
            case 0 -> leds & ~bit;
            case 1 -> leds | bit;
            case 2 -> leds ^ bit;
            default -> throw new IllegalArgumentException("LED action " + action
                    + " must be 0 (off), 1 (on) or 2 (toggle)");
        };
    }

    /** @return the LEDs as a bit mask: bit 0 the lateral LED, bit 1 the front LED; 1 = on */
    public int leds() {
        return leds;
    }
}
