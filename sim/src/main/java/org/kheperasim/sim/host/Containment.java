package org.kheperasim.sim.host;

import java.time.Clock;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * What the controller class loader puts in place of the calls that would let controller code end
 * the application, stall a run out of sight of the simulated clock, or read the wall clock:
 * {@code System.exit}, {@code Runtime.exit/halt}, {@code LockSupport.park*}, {@code Object.wait},
 * {@code Instant.now()} and the other {@code java.time} clocks (the thread calls are in
 * {@link ThreadHooks}). Each has
 * the signature of the call it replaces (an instance method's receiver comes first).
 *
 * <p>Outside a run (no simulated clock on the thread) the ones that are harmless there do what the
 * original would; ending the application never happens.
 */
public final class Containment {
    private Containment() {
    }

    /** Replaces {@link System#exit}: the run ends with a named fault; the application stays. */
    public static void exit(int status) {
        refuse("called System.exit(" + status + ")");
    }

    /**
     * Put at the start of every handler that catches {@code Throwable} or {@code Error} in
     * controller code: a stop of the simulator goes on unwinding, so a {@code catch (Throwable)}
     * loop cannot keep a stopped controller alive.
     *
     * @param caught what the handler caught
     */
    public static void rethrowIfStopped(Throwable caught) {
        if (caught instanceof ControllerStoppedError stop) {
            throw stop;
        }
    }

    /** Replaces {@link Runtime#exit}. */
    public static void exit(Runtime runtime, int status) {
        refuse("called Runtime.exit(" + status + ")");
    }

    /** Replaces {@link Runtime#halt}. */
    public static void halt(Runtime runtime, int status) {
        refuse("called Runtime.halt(" + status + ")");
    }

    /** Replaces {@link Runtime#addShutdownHook}: a controller's code must not outlive its run. */
    public static void addShutdownHook(Runtime runtime, Thread hook) {
        refuse("called Runtime.addShutdownHook");
    }

    static void refuse(String what) {
        SimClock.Clock c = SimClock.current();
        if (c != null) {
            c.brokeRule(what);
        }
        throw new ControllerStoppedError("the controller " + what + "; a controller may not end the application"
                + " (return from run() to end the controller)");
    }

    /** Replaces {@link LockSupport#parkNanos(long)}: simulated time passes. */
    public static void parkNanos(long nanos) {
        sleepQuietly(nanos);
    }

    /** Replaces {@link LockSupport#parkNanos(Object, long)}. */
    public static void parkNanos(Object blocker, long nanos) {
        sleepQuietly(nanos);
    }

    /** Replaces {@link LockSupport#parkUntil(long)}: the deadline is on the simulated clock. */
    public static void parkUntil(long deadlineMillis) {
        sleepQuietly(TimeUnit.MILLISECONDS.toNanos(deadlineMillis - SimClock.currentTimeMillis()));
    }

    /** Replaces {@link LockSupport#parkUntil(Object, long)}. */
    public static void parkUntil(Object blocker, long deadlineMillis) {
        parkUntil(deadlineMillis);
    }

    /** Replaces {@link LockSupport#park()}: on the controller's thread nothing could ever wake it. */
    public static void park() {
        SimClock.Clock c = SimClock.current();
        if (c != null && c.onControllerThread()) {
            refuse("called LockSupport.park() with nothing to wake it (in the simulator only the controller's"
                    + " thread runs; use Thread.sleep)");
        }
        LockSupport.park();
    }

    /** Replaces {@link LockSupport#park(Object)}. */
    public static void park(Object blocker) {
        park();
    }

    private static void sleepQuietly(long nanos) {
        if (nanos <= 0) {
            return;
        }
        try {
            SimClock.sleep(TimeUnit.NANOSECONDS, nanos);
        } catch (InterruptedException e) {
            // Like park, an interrupt just ends the wait; the flag stays set.
            Thread.currentThread().interrupt();
        }
    }

    // ------------------------------------------------------------------ the simulated wall clock

    /** @return a {@link Clock} that reads the simulated time (UTC) */
    public static Clock clockUTC() {
        return new Simulated(ZoneOffset.UTC);
    }

    /** @return a {@link Clock} that reads the simulated time in the default zone */
    public static Clock clockDefaultZone() {
        return new Simulated(ZoneId.systemDefault());
    }

    /** Replaces {@link Instant#now()}. */
    public static Instant instantNow() {
        return Instant.ofEpochMilli(SimClock.currentTimeMillis());
    }

    /** Replaces {@link LocalDateTime#now()}. */
    public static LocalDateTime localDateTimeNow() {
        return LocalDateTime.now(clockDefaultZone());
    }

    /** Replaces {@link LocalDate#now()}. */
    public static LocalDate localDateNow() {
        return LocalDate.now(clockDefaultZone());
    }

    /** Replaces {@link LocalTime#now()}. */
    public static LocalTime localTimeNow() {
        return LocalTime.now(clockDefaultZone());
    }

    /** Replaces {@link ZonedDateTime#now()}. */
    public static ZonedDateTime zonedDateTimeNow() {
        return ZonedDateTime.now(clockDefaultZone());
    }

    /** The wall clock of the robot's world: the simulated time. */
    private static final class Simulated extends Clock {
        private final ZoneId zone;

        Simulated(ZoneId zone) {
            this.zone = zone;
        }

        @Override
        public ZoneId getZone() {
            return zone;
        }

        @Override
        public Clock withZone(ZoneId other) {
            return new Simulated(other);
        }

        @Override
        public Instant instant() {
            return instantNow();
        }

        @Override
        public long millis() {
            return SimClock.currentTimeMillis();
        }
    }
}
