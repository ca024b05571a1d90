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
    /** Where it is, by the encoders, from the middle of its start cell facing up the maze. */
    private Odometry odometry;
    private int stalled;
    private int lost;

    @Override
    protected void setup() {
        odometry = new Odometry(CELL_MM / 2, CELL_MM / 2, StrictMath.PI / 2, leftPosition(), rightPosition());
        enterCell();
    }

    @Override
    protected void doWork() {
        prox.addProximity(sensors());
        int left = prox.value(IrSensor.LEFT_90);
        int left45 = prox.value(IrSensor.LEFT_45);
        int front = StrictMath.max(prox.value(IrSensor.FRONT_LEFT), prox.value(IrSensor.FRONT_RIGHT));
        boolean moved = track();
        if (stalled >= 10) {
            // Half a second of wheels turning without going anywhere: back off and turn right.
            setSpeeds(-4, -4);
            sleepMillis(400);
            setSpeeds(4, -4);
            sleepMillis(300);
            stalled = 0;
            track();
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
    private boolean track() {
        odometry.update(leftPosition(), rightPosition());
        enterCell();
        return odometry.lastStep() > 0.8;
    }

    private void enterCell() {
        long col = (long) StrictMath.floor(odometry.x() / CELL_MM);
        long row = (long) StrictMath.floor(odometry.y() / CELL_MM);
        if (visited.add(col << 32 ^ (row & 0xFFFFFFFFL))) {
            print("entered cell (" + col + ", " + row + ") by odometry; " + visited.size() + " cells so far");
        }
    }
}
