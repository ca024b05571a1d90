package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * The threads of one controller in the lockstep, and the monitors they hold: which of them runs
 * next, in simulated time. The controller's own thread comes first; a thread its code starts joins
 * when {@code start()} is called and first runs, at the simulated time it was started, when the
 * starter gives up the turn.
 *
 * <p>All of a controller's threads share one timeline, as if on one processor: the thread that
 * runs next is the one due earliest (the first started among equals); a thread that sleeps lets the
 * others run meanwhile. A thread blocked on a monitor another of them owns, or waiting in
 * {@code Object.wait}, is not due until the monitor is free and it was notified (or its timeout
 * passed). Only the thread holding the turn calls these methods.
 */
final class ControllerThreads {
    /** A monitor owned in the lockstep, and how many times its owner has entered it. */
    private static final class Held {
        final Participant owner;
        int count;

        Held(Participant owner, int count) {
            this.owner = owner;
            this.count = count;
        }
    }

    private final List<Participant> all = new ArrayList<>();
    private final Map<Object, Held> held = new IdentityHashMap<>();
    private Participant running;
    private long waits;
    /** Threads the controller's constructor started, before its own thread exists. */
    private final List<Thread> pending = new ArrayList<>();
    /** Threads its code interrupted before they were started: each starts interrupted, as in the JDK. */
    private final List<Thread> interruptedUnstarted = new ArrayList<>();

    /**
     * The controller's own thread, participant 0, due at once; then the threads its constructor
     * started, due at once too (they first run when it first gives up the turn).
     */
    void main(Thread controller) {
        Participant p = participant(0, controller, 0);
        all.add(p);
        running = p;
        for (Thread t : pending) {
            all.add(participant(all.size(), t, 0));
        }
        pending.clear();
    }

    /** A thread the controller's constructor starts. */
    void addPending(Thread t) {
        if (indexOf(pending, t) >= 0 || ThreadRunners.started(t)) {
            throw new IllegalThreadStateException("thread '" + t.getName() + "' was already started");
        }
        pending.add(t);
    }

    Participant main() {
        return all.get(0);
    }

    /** @return the participant that holds (or last held) the turn */
    Participant running() {
        return running;
    }

    void run(Participant p) {
        running = p;
    }

    /**
     * @return {@code p}'s interrupt flag as the thread holding the turn may see it: the same however the threads were
     *     scheduled
     */
    boolean interrupted(Participant p) {
        return p == running || p.done ? p.runner.isInterrupted() : p.interruptPending;
    }

    /**
     * @return {@code p}'s state as the thread holding the turn sees it: running or due to run,
     *     ended, blocked on a monitor, or waiting (with a timeout or not)
     */
    Thread.State state(Participant p) {
        if (p == running || !p.started) {
            // A participant exists from its start(): not run yet, it is runnable.
            return Thread.State.RUNNABLE;
        }
        if (p.done) {
            return Thread.State.TERMINATED;
        }
        return p.lock != null && !p.waiting ? Thread.State.BLOCKED : p.waitingAs;
    }

    /** @return true while the controller has no other thread: the fast paths apply */
    boolean single() {
        return all.size() == 1;
    }

    /** @return a copy of every participant, in order */
    List<Participant> all() {
        return List.copyOf(all);
    }

    /** @return the participant whose thread {@code t} is, or null */
    Participant of(Thread t) {
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).is(t)) {
                return all.get(i);
            }
        }
        return null;
    }

    /** @return the participant waiting on {@code seat}, or null */
    Participant at(Turn.Seat seat) {
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).seat == seat) {
                return all.get(i);
            }
        }
        return null;
    }

    /**
     * A thread the controller starts: it is due at {@code now} and starts when it first runs.
     *
     * @throws IllegalThreadStateException when it was started before, as {@code Thread.start} would
     */
    Participant add(Thread t, long now) {
        if (of(t) != null || ThreadRunners.started(t)) {
            throw new IllegalThreadStateException("thread '" + t.getName() + "' was already started");
        }
        Participant p = participant(all.size(), t, now);
        all.add(p);
        return p;
    }

    /** Its code interrupted {@code t}, which it has not started yet (nor the lockstep). */
    void interruptedUnstarted(Thread t) {
        if (indexOf(interruptedUnstarted, t) < 0) {
            interruptedUnstarted.add(t);
        }
    }

    private Participant participant(int index, Thread t, long wake) {
        Participant p = new Participant(index, t, wake);
        int early = indexOf(interruptedUnstarted, t);
        if (early >= 0) {
            interruptedUnstarted.remove(early);
            p.interruptPending = true;
        }
        return p;
    }

    /** By identity: a thread's {@code equals} is its class's to override. */
    private static int indexOf(List<Thread> list, Thread t) {
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i) == t) {
                return i;
            }
        }
        return -1;
    }

    private boolean runnable(Participant p) {
        if (p.done || p.wake == Long.MAX_VALUE) {
            return false;
        }
        if (p.lock == null) {
            return true;
        }
        Held h = held.get(p.lock);
        return h == null || h.owner == p;
    }

    /** @return the earliest simulated time a thread is due at, ns; {@link Long#MAX_VALUE} when none is */
    long earliest() {
        long w = Long.MAX_VALUE;
        for (int i = 0; i < all.size(); i++) {
            Participant p = all.get(i);
            if (p.wake < w && runnable(p)) {
                w = p.wake;
            }
        }
        return w;
    }

    /**
     * @param now the controller's time, ns
     * @param limit the end of its slice, ns
     * @return the thread to run next in the slice: the runnable one due earliest (the first among
     *     equals), or null when none can start before {@code limit}
     */
    Participant pick(long now, long limit) {
        if (now >= limit) {
            return null;
        }
        Participant best = null;
        for (int i = 0; i < all.size(); i++) {
            Participant p = all.get(i);
            if (p.wake < limit && (best == null || p.wake < best.wake) && runnable(p)) {
                best = p;
            }
        }
        return best;
    }

    /** @return true when threads remain but none can ever run again: each waits for another */
    boolean deadlocked() {
        boolean alive = false;
        for (Participant p : all) {
            if (!p.done) {
                alive = true;
                if (runnable(p)) {
                    return false;
                }
            }
        }
        return alive;
    }

    /** @return what each live thread waits for, for the user */
    String describeWaits() {
        StringBuilder sb = new StringBuilder();
        for (Participant p : all) {
            if (p.done) {
                continue;
            }
            if (!sb.isEmpty()) {
                sb.append("; ");
            }
            Held h = p.lock == null ? null : held.get(p.lock);
            sb.append(p.index == 0 ? "the controller's own thread" : "thread " + p);
            if (p.waiting) {
                sb.append(" waits in wait() on a ").append(MonitorStandIn.typeName(p.lock))
                        .append(" that nobody notifies");
            } else if (h != null) {
                sb.append(" waits for a lock on a ").append(MonitorStandIn.typeName(p.lock))
                        .append(" held by ")
                        .append(h.owner.index == 0 ? "the controller's own thread" : "thread " + h.owner);
            } else {
                sb.append(" waits");
            }
        }
        return sb.toString();
    }

    // ------------------------------------------------------------------ monitors

    /** @return true when {@code me} entered the monitor (it was free or already its own) */
    boolean tryEnter(Object monitor, Participant me) {
        Held h = held.get(monitor);
        if (h == null) {
            held.put(monitor, new Held(me, 1));
            return true;
        }
        if (h.owner == me) {
            h.count++;
            return true;
        }
        return false;
    }

    void exit(Object monitor, Participant me) {
        Held h = held.get(monitor);
        if (h != null && h.owner == me && --h.count == 0) {
            held.remove(monitor);
        }
    }

    /** {@code me} begins to wait on the monitor: it lets go of it whole, until notified or {@code deadline}. */
    void beginWait(Participant me, Object monitor, long deadline) {
        Held h = held.remove(monitor);
        me.lockCount = h != null && h.owner == me ? h.count : 1;
        me.lock = monitor;
        me.waiting = true;
        me.waitOrder = waits++;
        me.wake = deadline;
    }

    /** {@code me} runs again after its wait: it owns the monitor as often as before. */
    void endWait(Participant me) {
        held.put(me.lock, new Held(me, me.lockCount));
        me.lock = null;
        me.waiting = false;
    }

    /** Notify one thread waiting on the monitor (the longest waiting), or all of them: each is due at {@code now}. */
    void notify(Object monitor, boolean everyone, long now) {
        Participant first = null;
        for (Participant p : all) {
            if (p.waiting && p.lock == monitor && !p.done) {
                if (everyone) {
                    wakeFromWait(p, now);
                } else if (first == null || p.waitOrder < first.waitOrder) {
                    first = p;
                }
            }
        }
        if (first != null) {
            wakeFromWait(first, now);
        }
    }

    private static void wakeFromWait(Participant p, long now) {
        p.waiting = false;
        p.wake = now;
    }

    /** Another thread interrupted {@code p}: if it sleeps or waits, it is due at {@code now}. */
    void interrupted(Participant p, long now) {
        if (p.done || !p.started) {
            return;
        }
        if (p.waiting) {
            wakeFromWait(p, now);
        } else if (p.lock == null && p.wake > now) {
            p.wake = now;
        }
    }

    /** A thread has ended: it never runs again, and the monitors it still held are free. */
    void ended(Participant p) {
        p.done = true;
        p.wake = Long.MAX_VALUE;
        held.values().removeIf(h -> h.owner == p);
    }
}
