package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Reports what {@code getState()} says of threads it started, in each situation a platform thread
 * has a state for: busy, sleeping, joining, waiting with and without a timeout, blocked on a lock.
 */
public class ThreadStates extends Thread {
    private final CurrentRobotState state;
    private final MessagePasser mp;
    private final Object lock = new Object();
    private volatile boolean go;

    public ThreadStates(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
        this.mp = mp;
    }

    private static void nap(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void run() {
        Thread busy = new Thread(() -> {
            while (!go) {
                state.getSensorValues()[0].getDistValue();
            }
        }, "busy");
        busy.start();
        nap(5);
        String busyState = busy.getState().toString();
        go = true;
        Thread sleeper = new Thread(() -> nap(50), "sleeper");
        Thread joiner = new Thread(() -> {
            try {
                sleeper.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "joiner");
        sleeper.start();
        joiner.start();
        nap(5);
        mp.sendMessage("states busy " + busyState + " sleeper " + sleeper.getState() + " joiner " + joiner.getState());
        nap(60);
        Thread waiter = new Thread(() -> {
            synchronized (lock) {
                try {
                    lock.wait();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }, "waiter");
        Thread timed = new Thread(() -> {
            synchronized (lock) {
                try {
                    lock.wait(1000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }, "timed");
        waiter.start();
        timed.start();
        nap(5);
        String waiting = "waiter " + waiter.getState() + " timed " + timed.getState();
        synchronized (lock) {
            lock.notifyAll();
            nap(5);
            mp.sendMessage("states " + waiting + " notified " + waiter.getState());
        }
        nap(5);
        mp.sendMessage("states after " + waiter.getState() + " " + timed.getState() + " " + busy.getState());
    }
}
