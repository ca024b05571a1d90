package edu.wsu.KheperaSimulator;

/**
 * What the WSU Khepera Simulator runs: a {@link Runnable} whose {@code run()} calls
 * {@link #doWork()} over and over and {@link #close()} once at the end. Controllers extend
 * {@link RobotController}, which implements this loop.
 */
public interface Controller extends Runnable {

    /**
     * One step of the controller: read sensors, set speeds, maybe sleep. Called repeatedly, with a
     * pause between calls, until the controller is finished.
     *
     * @throws Exception anything; the controller is then stopped and the exception reported
     */
    void doWork() throws Exception;

    /**
     * Called once after the last {@link #doWork()}.
     *
     * @throws Exception anything; it is reported
     */
    void close() throws Exception;
}
