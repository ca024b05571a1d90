package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Threads that talk through wait/notify, join and interrupt: a producer that hands over a value
 * after 300 ms, a sleeper interrupted after 100 ms, and joins; each event reported with its
 * simulated time in ms since the start. It also reports what its code sees of its threads: itself
 * as {@code Thread.currentThread()}, and its interrupt flag (whichever thread runs its code, see
 * {@code ThreadRunners}).
 */
public class WaitNotify extends Thread {
    private final MessagePasser mp;
    private final Object box = new Object();
    private Integer value;
    private long t0;

    public WaitNotify(CurrentRobotState state, MessagePasser mp) {
        this.mp = mp;
    }

    private long ms() {
        return System.currentTimeMillis() - t0;
    }

    @Override
    public void run() {
        t0 = System.currentTimeMillis();
        mp.sendMessage("self " + (Thread.currentThread() == this) + " " + Thread.currentThread().getName().equals(getName()));
        interrupt();
        boolean flagged = isInterrupted();
        boolean cleared = Thread.interrupted();
        mp.sendMessage("interrupt flag " + flagged + " " + cleared + " " + isInterrupted());
        Thread producer = new Thread(() -> {
            try {
                Thread.sleep(300);
            } catch (InterruptedException e) {
                return;
            }
            synchronized (box) {
                value = 42;
                box.notifyAll();
            }
        }, "producer");
        Thread sleeper = new Thread(() -> {
            try {
                Thread.sleep(10_000);
                mp.sendMessage("sleeper slept on");
            } catch (InterruptedException e) {
                mp.sendMessage("sleeper interrupted at " + ms());
                mp.sendMessage("sleeper is " + Thread.currentThread().getName());
            }
        }, "sleeper");
        producer.start();
        sleeper.start();
        mp.sendMessage("alive " + producer.isAlive() + " " + sleeper.isAlive());
        try {
            Thread.sleep(100);
            sleeper.interrupt();
            mp.sendMessage("sleeper flagged " + sleeper.isInterrupted());
            synchronized (box) {
                while (value == null) {
                    box.wait();
                }
            }
            mp.sendMessage("got " + value + " at " + ms());
            producer.join();
            sleeper.join();
            mp.sendMessage("joined at " + ms() + " alive " + producer.isAlive() + " " + sleeper.isAlive());
        } catch (InterruptedException e) {
            mp.sendMessage("main interrupted");
        }
    }
}
