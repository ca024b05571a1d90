package org.kheperasim.testcontrollers;

import edu.wsu.KheperaSimulator.RobotController;

/**
 * A WSU controller that reports, after 300 loops, the simulated time between each two of its
 * {@code doWork()} calls, in microseconds, on one printed line.
 */
public class WsuLoopClock extends RobotController {
    private final long[] at = new long[301];
    private int loops;

    @Override
    public void doWork() {
        if (loops < at.length) {
            at[loops++] = System.nanoTime();
            if (loops == at.length) {
                StringBuilder b = new StringBuilder("periods");
                for (int i = 1; i < at.length; i++) {
                    b.append(' ').append((at[i] - at[i - 1]) / 1000);
                }
                System.out.println(b);
            }
        }
    }

    @Override
    public void close() {
    }
}
