package org.kheperasim.link.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * {@link Forward} whose killControl() and interrupt() block for 30 s, whose start() and
 * setUncaughtExceptionHandler() spin a while before doing their work, and whose toString() throws:
 * robot-link's own thread must call none of them.
 */
public class Overriding extends Thread {
    private final CurrentRobotState robot;
    static volatile long n;

    public Overriding(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
    }

    /** Spins (burning a core) for a short while, as a slow override would. */
    private static void spin(long millis) {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (System.nanoTime() < end) {
            n++;
        }
    }

    /** Blocks, uninterruptibly, for a long while (without burning a core), as an override waiting for something would. */
    private static void block(long millis) {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (System.nanoTime() < end) {
            try {
                Thread.sleep(StrictMath.max(1, (end - System.nanoTime()) / 1_000_000L));
            } catch (InterruptedException e) {
                // keep blocking
            }
        }
    }

    public void killControl() {
        block(30_000);
    }

    @Override
    public void interrupt() {
        block(30_000);
    }

    @Override
    public synchronized void start() {
        spin(500);
        super.start();
    }

    @Override
    public void setUncaughtExceptionHandler(UncaughtExceptionHandler eh) {
        spin(500);
        super.setUncaughtExceptionHandler(eh);
    }

    @Override
    public String toString() {
        throw new IllegalStateException("no name");
    }

    @Override
    public void run() {
        while (n >= 0) {
            robot.getMotorState().setMotorSpeeds(5, 5);
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
