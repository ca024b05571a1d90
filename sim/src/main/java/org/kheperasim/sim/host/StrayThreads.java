package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.List;

/**
 * Threads a controller's code started from outside the lockstep (from a timer's thread, or its own
 * window's event thread): they run on the wall clock, are interrupted when the controller is
 * stopped, and end with the run; one that does not within the grace period is reported as left
 * behind. Whichever thread runs one's code ({@link ThreadRunners#strayRunner}), the simulator asks
 * only that thread, never the student's overrides of the object's methods.
 */
final class StrayThreads {
    /** A thread the controller started, and the thread running its code (itself, or a runner). */
    private record Stray(Thread object, Thread runner) {
    }

    private final ControllerHost host;
    private final List<Stray> threads = new ArrayList<>();

    StrayThreads(ControllerHost host) {
        this.host = host;
    }

    /**
     * Start a thread the controller's code starts: daemon, its exceptions reported.
     *
     * @param t the thread
     * @param contained true when the controller's code is contained
     */
    void start(Thread t, boolean contained) {
        Thread runner = ThreadRunners.strayRunner(t, contained, (th, e) -> {
            if (!(e instanceof ControllerStoppedError)) {
                String what;
                try {
                    what = String.valueOf(e);
                } catch (RuntimeException | Error unreadable) {
                    what = ControllerFailures.unreadable(e, unreadable);
                }
                host.say(ConsoleLine.Kind.ERROR, "a thread the controller started (" + t.getName() + ") threw " + what);
            }
        });
        synchronized (threads) {
            threads.add(new Stray(t, runner));
        }
        runner.start();
    }

    /** @return the ones still alive */
    List<Stray> live() {
        synchronized (threads) {
            return threads.stream().filter(s -> s.runner().isAlive()).toList();
        }
    }

    void interrupt() {
        live().forEach(StrayThreads::interrupt);
    }

    private static void interrupt(Stray s) {
        if (s.runner() != s.object()) {
            s.runner().interrupt();
        } else {
            s.object().interrupt(); // the JDK's: a class overriding it runs on a runner
        }
    }

    /** Interrupt them and wait up to {@code graceMillis} for them to unwind (at their next loop checkpoint or call). */
    void end(long graceMillis) {
        List<Stray> alive = live();
        if (alive.isEmpty()) {
            return;
        }
        // While they unwind, every loop checkpoint of theirs looks for the stop.
        SimClock.stopRequested();
        try {
            long deadline = System.nanoTime() + graceMillis * 1_000_000L;
            for (Stray s : alive) {
                interrupt(s);
                try {
                    s.runner().join(StrictMath.max(1, (deadline - System.nanoTime()) / 1_000_000L));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
                if (s.runner().isAlive()) {
                    host.say(ConsoleLine.Kind.ERROR,
                            "a thread the controller started (" + s.object().getName() + ") did not end"
                            + " with the run; it was left behind");
                }
            }
        } finally {
            SimClock.stopSettled();
        }
    }
}
