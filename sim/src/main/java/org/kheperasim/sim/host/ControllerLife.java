package org.kheperasim.sim.host;

import java.util.Objects;

/**
 * A controller's life, the one state machine both hosts use: not started, running, stopping with a
 * reason, ended with a status. Several threads tell it what happened (the controller's own threads,
 * the run's owner, the watchdogs); each event is one synchronized transition of an immutable
 * {@link State}, so no two of them can decide the end differently, and every host reads the answer
 * in one volatile read (the API's stop check, on every call).
 *
 * <p>The transitions are {@link #next}, a pure function: the table test goes over every state and
 * event. The rules, in short: the first fault decides how a controller ends (a stop request does
 * not, so a fault after it still names the cause); once ended, nothing changes the status; a
 * controller whose own thread hung or would not stop is ended and its thread let go
 * ({@link State#abandoned()}), so that it never touches the turn again.
 *
 * <p>What it does not decide: when to hand the turn over (the {@link Lockstep} and the clocks), and
 * what to tell the student (the hosts, with {@link ControllerFailures}).
 */
final class ControllerLife {

    /** Where a controller is. */
    enum Phase {
        /** Constructed; the engine has not given it a turn yet. */
        NOT_STARTED,
        /** Running (or sleeping) in lockstep with the engine. */
        RUNNING,
        /** Asked to stop, or stopped by a fault: its code unwinds at its next API call or loop. */
        STOPPING,
        /** Its code no longer runs (or runs abandoned); its status is final. */
        ENDED
    }

    /** What can happen to a controller. */
    enum Event {
        /** The engine gives it its first turn (its first step). */
        START,
        /** The run asks it to stop: the run's end, the user's Stop, a signal. */
        STOP,
        /** A fault of its own decides how it ends (a rule broken, the heap filled, a step that hung): it is stopped. */
        FAULT,
        /** Its own thread made no progress for the hang timeout: it ends hung, its thread abandoned. */
        HUNG,
        /** A thread it started made no progress for the hang timeout: it ends hung (that thread is stopped). */
        HELPER_HUNG,
        /** All its threads wait for each other: it ends hung, unless a fault already decides its end. */
        DEADLOCKED,
        /** Its code is over: {@code run()} or the step returned or threw, with the status that gives. */
        UNWOUND,
        /** It did not unwind within the grace after being asked to stop: it ends stopped, its thread abandoned. */
        LEFT_BEHIND
    }

    /**
     * The life at one moment.
     *
     * @param phase where it is
     * @param reason while stopping or ended: the fault that decided the end, or null when it was only asked to stop
     * @param status what it counts as now ({@code NOT_STARTED}, {@code RUNNING} until it ends, then its end)
     * @param abandoned its own thread was let go while still running: it must never touch the turn again
     */
    record State(Phase phase, ControllerStatus reason, ControllerStatus status, boolean abandoned) {
        static final State INITIAL = new State(Phase.NOT_STARTED, null, ControllerStatus.NOT_STARTED, false);

        State {
            Objects.requireNonNull(phase);
            Objects.requireNonNull(status);
        }

        /** @return true once it must unwind (stopping or ended) */
        boolean stopRequested() {
            return phase == Phase.STOPPING || phase == Phase.ENDED;
        }

        private State stopping(ControllerStatus why) {
            return new State(Phase.STOPPING, why, ControllerStatus.RUNNING, false);
        }

        private State ended(ControllerStatus end, boolean letGo) {
            return new State(Phase.ENDED, reason, end, letGo);
        }
    }

    /**
     * The transition function.
     *
     * @param s the state now
     * @param e what happened
     * @param status with {@link Event#FAULT}: the end the fault decides; with {@link Event#UNWOUND}: the
     *               end its code's last act gives (FINISHED for a return, the verdict on what it threw);
     *               ignored otherwise
     * @return the state after it (the same object when the event changes nothing)
     */
    static State next(State s, Event e, ControllerStatus status) {
        if (s.phase() == Phase.ENDED) {
            return s;
        }
        return switch (e) {
            case START -> s.phase() == Phase.NOT_STARTED
                    ? new State(Phase.RUNNING, null, ControllerStatus.RUNNING, false) : s;
            // Before it ever ran there is nothing to unwind.
            case STOP -> switch (s.phase()) {
                case NOT_STARTED -> s.ended(ControllerStatus.STOPPED, false);
                case RUNNING -> s.stopping(null);
                default -> s;
            };
            case FAULT -> {
                requireEnd(e, status);
                if (s.phase() == Phase.NOT_STARTED) {
                    // Only a constructor can fault before the start: it never runs, the run is refused.
                    yield new State(Phase.ENDED, status, status, false);
                }
                yield s.reason() == null ? s.stopping(status) : s;
            }
            case HUNG -> s.ended(ControllerStatus.HUNG, true);
            case HELPER_HUNG -> s.ended(ControllerStatus.HUNG, false);
            // A fault already deciding the end keeps it: the controller is unwinding for it.
            case DEADLOCKED -> s.reason() == null ? s.ended(ControllerStatus.HUNG, false) : s;
            case UNWOUND -> {
                requireEnd(e, status);
                yield s.ended(s.reason() != null ? s.reason() : status, false);
            }
            case LEFT_BEHIND -> s.phase() == Phase.NOT_STARTED ? s.ended(ControllerStatus.STOPPED, false)
                    : s.ended(ControllerStatus.STOPPED, true);
        };
    }

    private static void requireEnd(Event e, ControllerStatus status) {
        if (status == null || !status.ended()) {
            throw new IllegalArgumentException(e + " needs the status it ends with, not " + status);
        }
    }

    /** Told once, when the controller first has to unwind: its loops start looking for the stop. */
    interface StopSignal {
        /** A stop is pending: loop checkpoints look for it. */
        void requested();

        /** The stop has been delivered: its own thread is over. */
        void settled();

        /** The run's {@link SimClock} counter, which makes loop checkpoints cheap while no stop is pending. */
        StopSignal SIM_CLOCK = new StopSignal() {
            @Override
            public void requested() {
                SimClock.stopRequested();
            }

            @Override
            public void settled() {
                SimClock.stopSettled();
            }
        };
    }

    private final StopSignal signal;
    private volatile State state = State.INITIAL;
    /** Set once the stop has been signalled (under this object's lock). */
    private boolean signalled;
    /** Set once its own thread is over, so its end is never waited for or signalled again. */
    private volatile boolean ownThreadOver;
    /** Its {@code killControl()} is still to be called, by its own thread, at its next look at the stop. */
    private boolean killPending;
    private volatile Throwable failure;
    private volatile String lastError;

    ControllerLife(StopSignal signal) {
        this.signal = signal;
    }

    ControllerLife() {
        this(StopSignal.SIM_CLOCK);
    }

    /** @return the state now (one volatile read) */
    State state() {
        return state;
    }

    /** @return where it is in its life, as the run reports it */
    ControllerStatus status() {
        return state.status();
    }

    /** @return true once its code must unwind; read on every API call */
    boolean stopRequested() {
        return state.stopRequested();
    }

    /**
     * Apply an event.
     *
     * @param e what happened
     * @param status see {@link #next}
     * @return true when the event changed the life (for a fault: it is the one that decides the end)
     */
    boolean on(Event e, ControllerStatus status) {
        synchronized (this) {
            State before = state;
            State after = next(before, e, status);
            if (after == before) {
                return false;
            }
            state = after;
            if (signalsStop(before, e)) {
                signalStop();
            }
            return true;
        }
    }

    /**
     * Does this (effective) event leave code of the controller's to unwind? Not when it has never
     * run, nor when its code ended by itself (its threads, if any, are stopped by the run's owner,
     * which signals then).
     */
    private static boolean signalsStop(State before, Event e) {
        return e != Event.UNWOUND && e != Event.START && !(e == Event.STOP && before.phase() == Phase.NOT_STARTED)
                && !(e == Event.LEFT_BEHIND && before.phase() == Phase.NOT_STARTED);
    }

    /** @param e an event that needs no status */
    boolean on(Event e) {
        return on(e, null);
    }

    /**
     * Make sure loop checkpoints look for the stop (once): threads the controller started must
     * unwind even after the controller itself has ended.
     */
    synchronized void signalStop() {
        if (!signalled) {
            signalled = true;
            signal.requested();
        }
    }

    /**
     * Its own thread is over (it returned or threw past its handler). Settles the stop signalled
     * for it, if any.
     *
     * @return true the first time
     */
    synchronized boolean ownThreadOver() {
        if (ownThreadOver) {
            return false;
        }
        ownThreadOver = true;
        if (signalled) {
            signal.settled();
        }
        return true;
    }

    /**
     * Ask for the controller's {@code killControl()}: asked to stop, or hung, while it ran. Its own
     * thread calls it (never the simulator's: it is the controller's code), once.
     */
    synchronized void wantKill() {
        killPending = true;
    }

    /**
     * @return true once after {@link #wantKill}: the caller, the controller's own thread, calls {@code killControl()}
     */
    synchronized boolean takeKill() {
        boolean k = killPending;
        killPending = false;
        return k;
    }

    /** @return true once its own thread is over */
    boolean isOwnThreadOver() {
        return ownThreadOver;
    }

    /**
     * @param e what the controller threw, which ended it; call this on the thread it was thrown on:
     *     its description is read there, once ({@link ReportedFailure})
     */
    void failedWith(Throwable e) {
        try {
            failure = ReportedFailure.of(e);
        } catch (VirtualMachineError full) {
            // No room for the copy (the heap just ran out): a JDK throwable is kept as it is, its methods are the
            // JDK's.
            failure = e.getClass().getClassLoader() == null ? e : null;
        }
    }

    /** @return what the controller threw, as the simulator's copy of it ({@link ReportedFailure}), or null */
    Throwable failure() {
        return failure;
    }

    /** @param message the last error told about the controller */
    void error(String message) {
        lastError = message;
    }

    /** @return the last error told about it (why it hung, broke a rule, ran out of heap), or null */
    String lastError() {
        return lastError;
    }
}
