package org.kheperasim.sim.host.loading;

import java.lang.StackWalker.Option;
import org.kheperasim.sim.host.ThreadHooks;

/**
 * Gives each robot's code its own monitors for the objects it does not own ({@link Monitors}): the
 * controller class loader puts {@link #own(Object, Class)} before every {@code monitorenter} of
 * contained code (and before the {@code monitorexit} that does not leave a stand-in already
 * entered), and points {@code Object.wait}, {@code notify}, {@code notifyAll} and
 * {@code Thread.holdsLock} here. Two robots that both lock {@code "swarm-lock"} or
 * {@code IrSensor.class} each lock a monitor of their own, so neither can stall the other, and a
 * robot's own threads still exclude each other.
 *
 * <p>Each hook takes the calling class last (a class constant the rewrite pushes: the table is its
 * loader's); the forms without it, for a method handle such as {@code lock::notifyAll} and for
 * class files older than Java 5, find the nearest controller class on the stack.
 */
public final class MonitorHooks {
    private static final StackWalker STACK = StackWalker.getInstance(Option.RETAIN_CLASS_REFERENCE);

    private MonitorHooks() {
    }

    /**
     * @param monitor what the code locks (may be null: locking it then throws as before)
     * @param caller the class whose code locks it
     * @return the monitor to lock instead: {@code monitor} itself when the caller's loader owns it
     */
    public static Object own(Object monitor, Class<?> caller) {
        if (monitor == null) {
            return null;
        }
        return caller.getClassLoader() instanceof ControllerClassLoader loader
                ? loader.monitors().of(monitor) : monitor;
    }

    /** {@link #own(Object, Class)} for the nearest controller class on the calling thread's stack. */
    public static Object own(Object monitor) {
        if (monitor == null) {
            return null;
        }
        ControllerClassLoader loader = STACK.walk(frames -> frames.map(f -> f.getDeclaringClass().getClassLoader())
                .filter(ControllerClassLoader.class::isInstance).map(ControllerClassLoader.class::cast)
                .findFirst().orElse(null));
        return loader == null ? monitor : loader.monitors().of(monitor);
    }

    /** Replaces {@link Object#wait()}. */
    public static void waitForever(Object monitor, Class<?> caller) throws InterruptedException {
        ThreadHooks.waitForever(own(nonNull(monitor), caller));
    }

    /** Replaces {@link Object#wait()} in a method handle. */
    public static void waitForever(Object monitor) throws InterruptedException {
        ThreadHooks.waitForever(own(nonNull(monitor)));
    }

    /** Replaces {@link Object#wait(long)}. */
    public static void waitFor(Object monitor, long millis, Class<?> caller) throws InterruptedException {
        ThreadHooks.waitFor(own(nonNull(monitor), caller), millis);
    }

    /** Replaces {@link Object#wait(long)} in a method handle. */
    public static void waitFor(Object monitor, long millis) throws InterruptedException {
        ThreadHooks.waitFor(own(nonNull(monitor)), millis);
    }

    /** Replaces {@link Object#wait(long, int)}. */
    public static void waitFor(Object monitor, long millis, int nanos, Class<?> caller) throws InterruptedException {
        ThreadHooks.waitFor(own(nonNull(monitor), caller), millis, nanos);
    }

    /** Replaces {@link Object#wait(long, int)} in a method handle. */
    public static void waitFor(Object monitor, long millis, int nanos) throws InterruptedException {
        ThreadHooks.waitFor(own(nonNull(monitor)), millis, nanos);
    }

    /** Replaces {@link Object#notify()}. */
    public static void notify(Object monitor, Class<?> caller) {
        ThreadHooks.notify(own(nonNull(monitor), caller));
    }

    /** Replaces {@link Object#notify()} in a method handle. */
    public static void notify(Object monitor) {
        ThreadHooks.notify(own(nonNull(monitor)));
    }

    /** Replaces {@link Object#notifyAll()}. */
    public static void notifyAll(Object monitor, Class<?> caller) {
        ThreadHooks.notifyAll(own(nonNull(monitor), caller));
    }

    /** Replaces {@link Object#notifyAll()} in a method handle. */
    public static void notifyAll(Object monitor) {
        ThreadHooks.notifyAll(own(nonNull(monitor)));
    }

    /** Replaces {@link Thread#holdsLock(Object)}. */
    public static boolean holdsLock(Object monitor, Class<?> caller) {
        return Thread.holdsLock(own(nonNull(monitor), caller));
    }

    /** Replaces {@link Thread#holdsLock(Object)} in a method handle. */
    public static boolean holdsLock(Object monitor) {
        return Thread.holdsLock(own(nonNull(monitor)));
    }

    /**
     * @param monitor a monitor the lockstep keeps a record of
     * @return the type of the object it is (or stands in for), for messages: {@code java.lang.String}
     */
    public static String typeName(Object monitor) {
        return Monitors.typeName(monitor);
    }

    /** As calling the method on null would: a NullPointerException. */
    private static Object nonNull(Object monitor) {
        if (monitor == null) {
            throw new NullPointerException("Cannot invoke a method of Object because the receiver is null");
        }
        return monitor;
    }
}
