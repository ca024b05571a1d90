package org.kheperasim.controllers;

import java.util.HashSet;
import java.util.Set;
import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.SensorFilter;

/**
 * Visits every cell of a maze (the paper's first assignment) by keeping its left side to a wall: in
 * a perfect maze, where every wall is joined to the border, that path passes through every cell and
 * back to the start. Three habits the paper's students learned the hard way are shown here:
 *
 * <ul>
 *   <li>filter the sensors ({@link SensorFilter}: a random spike must not make the robot swerve);
 *   <li>steer in proportion to the error (hold the wall at a set distance rather than bang-bang);
 *   <li>notice when the wheels turn but the robot does not move, and back out.
 * </ul>
 *
 * It also keeps a map by odometry: from the encoders it works out where it is, in cells of
 * {@link #CELL_MM} (the bundled mazes' lattice) counted from its start cell, and says in the console
 * each time it enters a cell it has not been in. Odometry drifts (wheels slip, the two wheels differ a
 * little), which the console shows on a long run: the map is a guide, the wall is the truth.
 */
public class MazeExplorer extends Controller {
    /** The maze's cell, mm (the bundled mazes: a fifth of 4 ft). */
    static final double CELL_MM = 243.84;
    /** Wheel travel per encoder pulse, mm, and the distance between the wheels, mm. */
    private static final double MM_PER_PULSE = 0.08;
    private static final double WHEEL_BASE_MM = 53.0;

    /** Cruising speed, units (1 unit = 8 mm/s). */
    private static final int CRUISE = 7;
    /** Left sensor reading to hold: about 25 mm between the robot's side and the wall. */
    private static final int SETPOINT = 420;
    /** Steering per unit of error, speed units per sensor count. */
    private static final double GAIN = 0.006;
    /** Front reading that means a wall ahead. */
    private static final int FRONT_BLOCKED = 350;
    /** Left readings under this: the wall on the left has ended (a wall end or an opening). */
    private static final int WALL_LOST = 80;
    /** Steps of swinging left (50 ms each) after which no wall end is near: go straight to find a wall. */
    private static final int SEARCH_AFTER = 120;

    private final SensorFilter prox = new SensorFilter();
    private final Set<Long> visited = new HashSet<>();
    private double x = CELL_MM / 2;
    private double y = CELL_MM / 2;
    private double heading = StrictMath.PI / 2;
    private int lastLeft;
    private int lastRight;
    private int stalled;
    private int lost;

    @Override
    protected void setup() {
        lastLeft = leftPosition();
        lastRight = rightPosition();
        enterCell();
    }

    @Override
    protected void doWork() {
        prox.addProximity(sensors());
        int left = prox.value(IrSensor.LEFT_90);
        int left45 = prox.value(IrSensor.LEFT_45);
        int front = StrictMath.max(prox.value(IrSensor.FRONT_LEFT), prox.value(IrSensor.FRONT_RIGHT));
        boolean moved = odometry();
        if (stalled >= 10) {
            // Half a second of wheels turning without going anywhere: back off and turn right.
            setSpeeds(-4, -4);
            sleepMillis(400);
            setSpeeds(4, -4);
            sleepMillis(300);
            stalled = 0;
            odometry();
            return;
        }
        if (front > FRONT_BLOCKED || left45 > 800) {
            setSpeeds(4, -4);                 // wall ahead: turn right on the spot
        } else if (left < WALL_LOST && left45 < WALL_LOST) {
            // The wall ended: swing left around its end. Swinging for long finds nothing (the start
            // in the middle of a room): then go straight until a wall comes, and follow that.
            lost++;
            if (lost < SEARCH_AFTER) {
                setSpeeds(2, 7);
            } else {
                setSpeeds(CRUISE, CRUISE);
            }
        } else {
            lost = 0;
            // Hold the wall: too close (reading high) steers right, too far steers left.
            double error = StrictMath.max(left, left45 - 150) - SETPOINT;
            int turn = (int) StrictMath.round(StrictMath.max(-3, StrictMath.min(3, GAIN * error)));
            setSpeeds(CRUISE + turn, CRUISE - turn);
        }
        stalled = moved ? 0 : stalled + 1;
        sleepMillis(50);
    }

    /** Dead reckoning from the encoders. @return true if the wheels moved since the last call */
    private boolean odometry() {
        int l = leftPosition();
        int r = rightPosition();
        double dl = (l - lastLeft) * MM_PER_PULSE;
        double dr = (r - lastRight) * MM_PER_PULSE;
        lastLeft = l;
        lastRight = r;
        double turn = (dr - dl) / WHEEL_BASE_MM;
        x += (dl + dr) / 2 * StrictMath.cos(heading + turn / 2);
        y += (dl + dr) / 2 * StrictMath.sin(heading + turn / 2);
        heading += turn;
        enterCell();
        return StrictMath.abs(dl) + StrictMath.abs(dr) > 0.8;
    }

    private void enterCell() {
        long col = (long) StrictMath.floor(x / CELL_MM);
        long row = (long) StrictMath.floor(y / CELL_MM);
        if (visited.add(col << 32 ^ (row & 0xFFFFFFFFL))) {
            print("entered cell (" + col + ", " + row + ") by odometry; " + visited.size() + " cells so far");
        }
    }
}
