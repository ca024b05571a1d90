package edu.wsu.KheperaSimulator;

import java.util.Optional;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.api.spi.TruePose;

/**
 * The robot's pose in the units of the later WSU fork's pose API ({@code getRobotAngle()},
 * {@code getRobotXPosition()}, {@code getRobotYPosition()}): the original's panel pixels, y down,
 * the heading in radians growing clockwise on the screen (see {@link WsuUnits}).
 *
 * <p>A backend that knows the truth (the simulator) gives it. A real robot does not know where it
 * is, so there the pose is integrated from the wheel positions since the run started, from the
 * original's start spot, and the console says so once: course code that steers by the pose then
 * still runs on the robot, as well as odometry allows (it drifts with wheel slip), instead of
 * failing.
 */
final class WsuPose {
    private final RobotPort port;
    private boolean noted;
    private boolean started;
    private int lastLeft;
    private int lastRight;
    private double x = WsuUnits.START_PX;
    private double y = WsuUnits.START_PX;
    /** Clockwise on the screen from east, radians. */
    private double angle;

    WsuPose(RobotPort port) {
        this.port = port;
    }

    /**
     * The run starts: odometry counts from here, at the original's start spot.
     *
     * @param left the left position counter now, pulses
     * @param right the right position counter now, pulses
     */
    synchronized void start(int left, int right) {
        started = true;
        lastLeft = left;
        lastRight = right;
        x = WsuUnits.START_PX;
        y = WsuUnits.START_PX;
        angle = 0;
    }

    /** @return the heading, radians in [0, 2π), growing clockwise on the screen, 0 facing east */
    float angle() {
        Optional<TruePose> truth = port.truePose();
        if (truth.isPresent()) {
            return (float) clockwise(truth.get().headingDeg());
        }
        synchronized (this) {
            integrate();
            return (float) angle;
        }
    }

    /** @return the centre's x, panel pixels from the left edge */
    int x() {
        Optional<TruePose> truth = port.truePose();
        if (truth.isPresent()) {
            return (int) StrictMath.round(truth.get().xMm() / WsuUnits.MM_PER_PX);
        }
        synchronized (this) {
            integrate();
            return (int) StrictMath.round(x);
        }
    }

    /** @return the centre's y, panel pixels down from the top edge */
    int y() {
        Optional<TruePose> truth = port.truePose();
        if (truth.isPresent()) {
            TruePose p = truth.get();
            return (int) StrictMath.round((p.arenaHeightMm() - p.yMm()) / WsuUnits.MM_PER_PX);
        }
        synchronized (this) {
            integrate();
            return (int) StrictMath.round(y);
        }
    }

    /** @param headingDeg counter-clockwise degrees, y up @return clockwise radians on a y-down screen, [0, 2π) */
    static double clockwise(double headingDeg) {
        double a = -StrictMath.toRadians(headingDeg);
        a %= 2 * StrictMath.PI;
        return a < 0 ? a + 2 * StrictMath.PI : a;
    }

    /** Follow the wheels since the last look: each stretch as an arc at its mean heading. */
    private void integrate() {
        int l = port.leftPosition();
        int r = port.rightPosition();
        if (!noted) {
            noted = true;
            port.message("note: getRobotAngle(), getRobotXPosition() and getRobotYPosition() come from the wheels'"
                    + " odometry on a real robot, counted from the original's start spot (263, 263) px facing east when"
                    + " the controller started; they drift as the wheels slip");
        }
        if (!started) {
            started = true;
            lastLeft = l;
            lastRight = r;
            return;
        }
        double dl = (l - lastLeft) * WsuUnits.MM_PER_PULSE;
        double dr = (r - lastRight) * WsuUnits.MM_PER_PULSE;
        lastLeft = l;
        lastRight = r;
        // Counter-clockwise turn in the arena is a clockwise decrease on the y-down screen.
        double turn = (dr - dl) / WsuUnits.WHEEL_BASE_MM;
        double mid = angle - turn / 2;
        double travelPx = (dl + dr) / 2 / WsuUnits.MM_PER_PX;
        x += travelPx * StrictMath.cos(mid);
        y += travelPx * StrictMath.sin(mid);
        angle = (angle - turn) % (2 * StrictMath.PI);
        if (angle < 0) {
            angle += 2 * StrictMath.PI;
        }
    }
}
