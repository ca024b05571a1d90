package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.List;

/**
 * Threads a controller's code started from outside the lockstep (from its own window's event
 * thread, say): they run on the wall clock, are interrupted when the controller is stopped, and end
 * with the run; one that does not within the grace period is reported as left behind.
 */
final class StrayThreads {
    private final ControllerHost host;
    private final List<Thread> threads = new ArrayList<>();

    StrayThreads(ControllerHost host) {
        this.host = host;
    }

    /** A thread about to be started: daemon, its exceptions reported. */
    void add(Thread t) {
        t.setDaemon(true);
        t.setUncaughtExceptionHandler((th, e) -> {
            if (!(e instanceof ControllerStoppedError)) {
                host.say(ConsoleLine.Kind.ERROR, "a thread the controller started (" + th.getName() + ") threw " + e);
            }
        });
        synchronized (threads) {
            threads.add(t);
        }
    }

    /** @return the ones still alive */
    List<Thread> live() {
        synchronized (threads) {
            return threads.stream().filter(Thread::isAlive).toList();
        }
    }

    void interrupt() {
        live().forEach(Thread::interrupt);
    }

    /** Interrupt them and wait up to {@code graceMillis} for them to unwind (at their next loop checkpoint or call). */
    void end(long graceMillis) {
        List<Thread> alive = live();
        if (alive.isEmpty()) {
            return;
        }
        // While they unwind, every loop checkpoint of theirs looks for the stop.
        SimClock.stopRequested();
        try {
            long deadline = System.nanoTime() + graceMillis * 1_000_000L;
            for (Thread t : alive) {
                t.interrupt();
                try {
                    t.join(StrictMath.max(1, (deadline - System.nanoTime()) / 1_000_000L));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
                if (t.isAlive()) {
                    host.say(ConsoleLine.Kind.ERROR, "a thread the controller started (" + t.getName() + ") did not end"
                            + " with the run; it was left behind");
                }
            }
        } finally {
            SimClock.stopSettled();
        }
    }
}
