package org.kheperasim.link.calibrate;

import java.util.concurrent.locks.LockSupport;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;

/**
 * The robot's side of the procedure: encoder-measured moves (position moves to counter targets,
 * waited for by reading the counters) and series of sensor readings at the scan's pace.
 */
final class RobotMoves {
    private static final long MOVE_TIMEOUT_NANOS = 30_000_000_000L;

    private final Session session;
    private final long scanNanos;

    /** @param session an open session @param scanMillis time between two readings (the robot's scan: 20 ms) */
    RobotMoves(Session session, long scanMillis) {
        this.session = session;
        this.scanNanos = scanMillis * 1_000_000L;
    }

    /** @return the wheel counters, pulses */
    int[] counters() throws SessionException {
        return session.exchange(session.dialect().readCounters()).ints();
    }

    /** Moves the wheels to these counters and waits until they are there (within 2 pulses). */
    void moveTo(int left, int right) throws SessionException {
        session.exchange(new Command.MoveToPosition(left, right));
        long end = System.nanoTime() + MOVE_TIMEOUT_NANOS;
        while (true) {
            int[] c = counters();
            if (StrictMath.abs(c[0] - left) <= 2 && StrictMath.abs(c[1] - right) <= 2) {
                return;
            }
            if (System.nanoTime() > end) {
                throw new IllegalStateException("the wheels did not reach " + left + "," + right + " within 30 s (at "
                        + c[0] + "," + c[1] + "): check that the robot can move freely, then run calibrate again");
            }
            LockSupport.parkNanos(20_000_000L);
        }
    }

    /** Moves both wheels by these pulses from where they are. */
    void moveBy(int left, int right) throws SessionException {
        int[] c = counters();
        moveTo(c[0] + left, c[1] + right);
    }

    /**
     * @param light ambient light (O) instead of proximity (N)
     * @param n how many readings
     * @return {@code readings[repeat][sensor]}
     */
    int[][] readings(boolean light, int n) throws SessionException {
        int[][] r = new int[n][];
        for (int i = 0; i < n; i++) {
            if (i > 0 && scanNanos > 0) {
                LockSupport.parkNanos(scanNanos);
            }
            r[i] = session.exchange(light ? session.dialect().readLight() : session.dialect().readProximity()).ints();
        }
        return r;
    }

    /** Runs both wheels at this speed for this long and stops; @return the counters' change */
    int[] run(int speed, long millis) throws SessionException {
        int[] a = counters();
        session.exchange(session.dialect().setSpeeds(speed, speed));
        LockSupport.parkNanos(millis * 1_000_000L);
        session.exchange(session.dialect().setSpeeds(0, 0));
        int[] b = counters();
        return new int[] {b[0] - a[0], b[1] - a[1]};
    }

    /** @param r readings @return each sensor's mean */
    static double[] mean(int[][] r) {
        double[] m = new double[r[0].length];
        for (int[] row : r) {
            for (int s = 0; s < m.length; s++) {
                m[s] += row[s];
            }
        }
        for (int s = 0; s < m.length; s++) {
            m[s] /= r.length;
        }
        return m;
    }
}
