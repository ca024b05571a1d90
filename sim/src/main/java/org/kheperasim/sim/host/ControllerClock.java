package org.kheperasim.sim.host;

import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * A controller's own simulated clock. Each API call costs {@code api.callCostUs} of simulated time
 * (that is how a busy loop makes time pass), {@code Thread.sleep(ms)} costs exactly {@code ms}, and
 * computing between calls costs nothing. The engine lets the controller run through one tick's
 * stretch of simulated time at a time ({@link #grant}); a call that reaches past it has the
 * {@link Lockstep} step the world forward on the controller's own thread (no hand-over) until some
 * controller must run again.
 *
 * <p>The class loader rewrites a controller's {@code Thread.sleep}, {@code System.nanoTime} and
 * friends onto this clock (through {@link SimClock}); calls from any other thread fall through to
 * the real ones.
 */
final class ControllerClock implements SimClock.Clock, PortClock {
    /**
     * Robot time starts at the Appendix controller's creation date, 2001-07-27T11:06:00Z, so
     * currentTimeMillis looks plausible (a literal: parsing the date would load the java.time
     * formatters at every start).
     */
    static final long EPOCH_MILLIS = 996_231_960_000L;

    /** The heap is looked at every 16 API calls (a few nanoseconds each, on average). */
    private static final int HEAP_LOOK_MASK = 15;
    /** How often a thread joining another looks whether it has ended, ns of simulated time. */
    private static final long JOIN_POLL_NANOS = 1_000_000L;

    private final ControllerHost host;
    private final ControllerThreads threads;
    private final long apiCostNanos;
    private final int jitterMaxMicros;
    private long apiCalls;
    // Only the thread holding the turn touches these (the turn is volatile).
    private long now;
    private long limit;

    ControllerClock(ControllerHost host, ControllerThreads threads, long apiCostNanos, int jitterMaxMicros) {
        this.host = host;
        this.threads = threads;
        this.apiCostNanos = apiCostNanos;
        this.jitterMaxMicros = jitterMaxMicros;
    }

    /** @return the controller's simulated time now, ns */
    @Override
    public long now() {
        return now;
    }

    /** @return when the controller next needs to run, ns: when its thread (or the first due of its threads) is due */
    long wake() {
        return threads.single() ? threads.main().wake : StrictMath.max(now, threads.earliest());
    }

    /** The engine grants the controller simulated time up to {@code limitNanos}. */
    void grant(long limitNanos) {
        limit = limitNanos;
    }

    /** @return API calls made so far; read without synchronisation by the watchdog */
    long apiCalls() {
        return apiCalls;
    }

    /** @return true on the thread of the controller's that holds the turn */
    boolean onTurn() {
        // Nobody runs yet while the controller is constructed.
        Participant running = threads.running();
        return running != null && Thread.currentThread() == running.runner;
    }

    /**
     * @return {@code p}'s interrupt flag as the thread holding the turn sees it (see
     *     {@link ControllerThreads#interrupted})
     */
    boolean interrupted(Participant p) {
        return threads.interrupted(p);
    }

    /** @return {@code p}'s state as the thread holding the turn sees it (see {@link ControllerThreads#state}) */
    Thread.State state(Participant p) {
        return threads.state(p);
    }

    /** @return the {@code Thread} object of the controller's thread holding the turn, as its code knows it */
    Thread runningThread() {
        return threads.running().thread;
    }

    /** Every API call starts here: the lockstep check. */
    @Override
    public void enter() {
        if (!onTurn()) {
            if (host.status() == ControllerStatus.NOT_STARTED) {
                return; // the controller's constructor looking around: free, no time passes
            }
            throw new IllegalStateException("the robot API was called from thread '" + Thread.currentThread().getName()
                    + "', which the controller's code did not start; in the simulator only the controller's"
                    + " thread and the threads it starts may use it (that keeps runs deterministic)");
        }
        // Inside the simulator's code until leave(): the watchdog never takes the turn from it there.
        Turn.Seat seat = enterSimulator();
        try {
            host.checkStop();
            if ((++apiCalls & HEAP_LOOK_MASK) == 0) {
                lookAtHeap();
            }
            if (now >= limit) {
                yieldTurn();
            }
        } catch (RuntimeException | Error e) {
            seat.leaveSimulator(Turn.STUDENT);
            throw e;
        }
    }

    /**
     * The running thread enters the simulator's code.
     *
     * @return its seat
     * @throws ControllerStoppedError if the watchdog has taken the turn from it: it must not touch the run
     */
    private Turn.Seat enterSimulator() {
        Turn.Seat seat = threads.running().seat;
        if (seat.enterSimulator() == Turn.TAKEN) {
            throw new ControllerStoppedError("controller " + host.name() + " was taken off the run");
        }
        return seat;
    }

    /** A controller that allocates without bound is stopped before the heap runs out. */
    private void lookAtHeap() {
        String full = HeapWatch.pressed();
        if (full != null) {
            host.exceededMemory(full);
            host.checkStop();
        }
    }

    /** Every API call ends here: it costs its simulated time. */
    @Override
    public void leave() {
        now += apiCostNanos;
        Participant running = threads.running();
        if (running != null) {
            // Back in the controller's code (a constructor's look around entered nothing: leaving changes nothing).
            running.seat.leaveSimulator(Turn.STUDENT);
        }
    }

    /** The running thread's slice is used up: step the world on this thread until it runs again. */
    private void yieldTurn() {
        threads.running().waitingAs = Thread.State.RUNNABLE;
        threads.running().wake = now;
        reschedule();
    }

    /** The running thread has set when it is due next: run whoever is due, and return when it runs again. */
    private void reschedule() {
        Participant me = threads.running();
        int before = me.seat.enterSimulator();
        if (before == Turn.TAKEN) {
            throw new ControllerStoppedError("controller " + host.name() + " was taken off the run");
        }
        try {
            me.interruptPending = Thread.currentThread().isInterrupted();
            if (!handOff(me)) {
                host.lockstep().turn().await(me.seat);
            }
        } finally {
            me.seat.leaveSimulator(before);
        }
        host.checkStop();
    }

    /**
     * Run the thread due next: {@code me} itself (true: it goes on at once), another of the
     * controller's threads, or, when none is due in this slice, the world, stepped on this thread
     * until some driver must run (false: the turn has been passed on).
     */
    private boolean handOff(Participant me) {
        jitter();
        Lockstep lockstep = host.lockstep();
        while (true) {
            Participant p = threads.pick(now, limit);
            if (p == me) {
                now = StrictMath.max(now, me.wake);
                return true;
            }
            if (p != null) {
                switchTo(p);
                return false;
            }
            if (!threads.single() && threads.deadlocked()) {
                host.deadlocked(threads.describeWaits());
            }
            if (!lockstep.stepWorldFor(host)) {
                return false;
            }
        }
    }

    /** The engine chose this controller: run its thread due first. Called by whoever holds the turn. */
    void runNext() {
        Participant p = threads.pick(now, limit);
        if (p == null) {
            host.lockstep().passTo(null);
        } else {
            switchTo(p);
        }
    }

    /** Give the turn to {@code p}, starting its thread the first time. Called by whoever holds the turn. */
    void switchTo(Participant p) {
        threads.run(p);
        now = StrictMath.max(now, p.wake);
        host.lockstep().turn().giveTo(p.seat);
        if (!p.started) {
            p.start();
        }
    }

    /** Random real-time delays at hand-offs, for the determinism tests. */
    private void jitter() {
        if (jitterMaxMicros > 0 && ThreadLocalRandom.current().nextInt(8) == 0) {
            LockSupport.parkNanos(ThreadLocalRandom.current().nextLong(jitterMaxMicros * 1000L + 1));
        }
    }

    @Override
    public void sleepNanos(long nanos) throws InterruptedException {
        if (!onTurn()) {
            TimeUnit.NANOSECONDS.sleep(nanos);
            return;
        }
        host.checkStop();
        if (Thread.interrupted()) {
            throw new InterruptedException("sleep interrupted");
        }
        apiCalls++;
        long d = StrictMath.max(nanos, apiCostNanos);
        if (threads.single()) {
            now += d;
            if (now >= limit) {
                yieldTurn();
            }
            return;
        }
        Participant me = threads.running();
        me.waitingAs = me.joining != null ? me.joining : Thread.State.TIMED_WAITING;
        me.wake = now + d;
        reschedule();
        if (Thread.interrupted()) {
            throw new InterruptedException("sleep interrupted");
        }
    }

    @Override
    public long nanoTime() {
        if (!onTurn()) {
            // The constructor sees the run's start; other threads the wall clock.
            return host.constructing() ? now : System.nanoTime();
        }
        enter();
        long t = now;
        leave();
        return t;
    }

    @Override
    public long currentTimeMillis() {
        if (!onTurn()) {
            return host.constructing() ? EPOCH_MILLIS + now / 1_000_000L : System.currentTimeMillis();
        }
        enter();
        long t = EPOCH_MILLIS + now / 1_000_000L;
        leave();
        return t;
    }

    @Override
    public void pause() {
        if (!onTurn()) {
            Thread.onSpinWait();
            return;
        }
        enter();
        leave();
    }

    @Override
    public void checkpoint() {
        // The controller's thread unwinds when asked to stop; so does every thread it started.
        host.checkStop();
    }

    @Override
    public boolean onControllerThread() {
        return onTurn();
    }

    /** @return true while the controller has threads besides the one running */
    boolean othersAlive() {
        for (Participant p : threads.all()) {
            if (p != threads.running() && !p.done) {
                return true;
            }
        }
        return false;
    }

    /** A line from the controller's code for the run's console. */
    @Override
    public void say(ConsoleLine.Kind kind, String text) {
        host.say(kind, text);
    }

    @Override
    public void brokeRule(String what) {
        host.brokeRule(what);
    }

    @Override
    public boolean adopt(Thread thread) {
        if (host.constructing()) {
            // Started by the controller's constructor: it first runs just after the controller's thread starts.
            threads.addPending(thread);
            return true;
        }
        if (!onTurn()) {
            host.adoptStray(thread);
            return true;
        }
        host.checkStop();
        host.prepare(threads.add(thread, now));
        return true;
    }

    // ------------------------------------------------------------------ monitors, waits, joins

    /** {@code synchronized} entry in controller code: a monitor another thread of the controller owns blocks. */
    void monitorEnter(Object monitor) {
        Participant me = threads.running();
        while (!threads.tryEnter(monitor, me)) {
            me.lock = monitor;
            me.wake = now;
            try {
                reschedule();
            } finally {
                me.lock = null;
            }
        }
    }

    void monitorExit(Object monitor) {
        threads.exit(monitor, threads.running());
    }

    /**
     * {@code monitor.wait(millis)} on the thread holding the turn: it lets go of the monitor and
     * the others run until it is notified or {@code millis} of simulated time have passed.
     */
    void waitOn(Object monitor, long millis) throws InterruptedException {
        host.checkStop();
        if (Thread.interrupted()) {
            throw new InterruptedException("wait interrupted");
        }
        apiCalls++;
        Participant me = threads.running();
        threads.beginWait(me, monitor, millis == 0 ? Long.MAX_VALUE : now + TimeUnit.MILLISECONDS.toNanos(millis));
        me.waitingAs = millis == 0 ? Thread.State.WAITING : Thread.State.TIMED_WAITING;
        me.interruptPending = false;
        me.seat.waitMonitor = monitor;
        int before = me.seat.enterSimulator();
        if (before == Turn.TAKEN) {
            me.seat.waitMonitor = null;
            throw new ControllerStoppedError("controller " + host.name() + " was taken off the run");
        }
        try {
            if (!handOff(me)) {
                awaitInWait(me, monitor);
            }
        } finally {
            me.seat.leaveSimulator(before);
            me.seat.waitMonitor = null;
        }
        threads.endWait(me);
        host.checkStop();
        if (Thread.interrupted()) {
            throw new InterruptedException("wait interrupted");
        }
    }

    /** Wait for the turn inside the monitor's real wait, so that the monitor is free meanwhile. */
    private void awaitInWait(Participant me, Object monitor) {
        Turn turn = host.lockstep().turn();
        turn.settle(me.seat);
        boolean interrupted = false;
        while (!turn.heldBy(me.seat)) {
            try {
                monitor.wait();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    void notifyWaiters(Object monitor, boolean everyone) {
        threads.notify(monitor, everyone, now);
    }

    /** @return the controller's thread {@code t}, or null when it is no thread of this controller */
    Participant participant(Thread t) {
        return threads.of(t);
    }

    void interrupt(Participant p) {
        threads.interrupted(p, now);
    }

    /** The controller's code interrupted {@code t} before starting it (on its own thread, or in its constructor). */
    void interruptedUnstarted(Thread t) {
        if (onTurn() || host.constructing()) {
            threads.interruptedUnstarted(t);
        }
    }

    /** {@code p.join(millis)}: the caller sleeps a millisecond at a time until {@code p} has ended. */
    void join(Participant p, long millis) throws InterruptedException {
        long deadline = millis == 0 ? Long.MAX_VALUE : now + TimeUnit.MILLISECONDS.toNanos(millis);
        Participant me = threads.running();
        me.joining = millis == 0 ? Thread.State.WAITING : Thread.State.TIMED_WAITING;
        try {
            while (!p.done && now < deadline) {
                sleepNanos(StrictMath.min(JOIN_POLL_NANOS, deadline - now));
            }
        } finally {
            me.joining = null;
        }
    }

    /** The controller has ended: it never needs to run again. */
    void ended() {
        threads.main().wake = Long.MAX_VALUE;
    }
}
