package org.kheperasim.sim.host;

import java.lang.reflect.Method;

/**
 * Which thread runs the code of a controller's thread (its own, or one it started): the
 * {@code Thread} object itself, a platform thread; or, on Java 24 and later, a virtual thread that
 * calls the object's {@code run()}.
 *
 * <p>Only one thread of a run holds the turn at a time, so a controller's threads only ever hand
 * the turn to each other. Between platform threads each hand-over wakes a parked thread through
 * the operating system (15 to 30 µs on a 2-core virtual machine); between virtual threads it is a
 * switch on the same carrier (under 1 µs), which is what lets tens and hundreds of thread-style
 * controllers share one arena fast. From Java 24 on a virtual thread that waits inside
 * {@code synchronized} code no longer holds its carrier (JEP 491), so student code that sleeps in a
 * synchronized method is as safe there as on a platform thread; before 24 it is not, and platform
 * threads are used. {@code -Dkheperasim.virtualThreads=false} chooses platform threads anyway.
 *
 * <p>The controller's code sees its own {@code Thread} object as before: the class loader sends
 * {@code Thread.currentThread()}, {@code isInterrupted()} and the other thread calls of controller
 * code to {@link ThreadHooks}, which answer for the object. Outside controller code (a stack trace, a
 * debugger) the running thread is the virtual one, named like the object.
 */
final class ThreadRunners {
    /** True when controller threads run as virtual threads in this JVM. */
    static final boolean VIRTUAL;
    private static final Method OF_VIRTUAL;
    private static final Method NAME;
    private static final Method HANDLER;
    private static final Method UNSTARTED;

    static {
        Method ofVirtual = null;
        Method name = null;
        Method handler = null;
        Method unstarted = null;
        boolean wanted = Runtime.version().feature() >= 24
                && !"false".equalsIgnoreCase(System.getProperty("kheperasim.virtualThreads"));
        if (wanted) {
            try {
                ofVirtual = Thread.class.getMethod("ofVirtual");
                Class<?> builder = Class.forName("java.lang.Thread$Builder");
                name = builder.getMethod("name", String.class);
                handler = builder.getMethod("uncaughtExceptionHandler", Thread.UncaughtExceptionHandler.class);
                unstarted = builder.getMethod("unstarted", Runnable.class);
            } catch (ReflectiveOperationException e) {
                wanted = false;
            }
        }
        VIRTUAL = wanted;
        OF_VIRTUAL = ofVirtual;
        NAME = name;
        HANDLER = handler;
        UNSTARTED = unstarted;
    }

    private ThreadRunners() {
    }

    /**
     * The thread to start for {@code thread}: the object itself, or a virtual thread that binds
     * {@code clock} and calls its {@code run()}, passing what it throws to the object's uncaught
     * exception handler.
     *
     * @param thread a controller's thread, not started
     * @param clock the controller's clock, bound in the runner
     * @return the thread to start
     */
    static Thread runnerOf(Thread thread, SimClock.Clock clock) {
        if (!VIRTUAL) {
            return thread;
        }
        Runnable task = () -> {
            SimClock.bind(clock);
            thread.run();
        };
        Thread.UncaughtExceptionHandler forward = (t, e) -> thread.getUncaughtExceptionHandler().uncaughtException(thread, e);
        try {
            Object builder = OF_VIRTUAL.invoke(null);
            builder = NAME.invoke(builder, thread.getName());
            builder = HANDLER.invoke(builder, forward);
            return (Thread) UNSTARTED.invoke(builder, task);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("could not make a virtual thread for '" + thread.getName() + "'", e);
        }
    }
}
