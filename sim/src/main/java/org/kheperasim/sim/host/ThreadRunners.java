package org.kheperasim.sim.host;

import java.lang.reflect.Method;

/**
 * Which thread runs the code of a controller's own thread: the {@code Thread} object itself, a
 * platform thread; or, on Java 24 and later with {@code -Dkheperasim.virtualThreads=true}, a virtual
 * thread that calls the object's {@code run()}.
 * Threads the controller's code starts stay platform threads (they may ask for a stack size, or
 * inherit thread-local values when they are made, which a virtual thread made later cannot honour).
 *
 * <p>Only one thread of a run holds the turn at a time, so a controller's threads only ever hand
 * the turn to each other. Between platform threads each hand-over wakes a parked thread through
 * the operating system: 2 to 4 µs on a 2-core virtual machine when the run's threads keep to one
 * core ({@link CpuAffinity}, Linux), 20 to 60 µs when the woken thread's idle core must be woken
 * too; between virtual threads it is a switch on the same carrier (under 1 µs). From Java 24 on a virtual thread that waits inside
 * {@code synchronized} code no longer holds its carrier (JEP 491), so student code that sleeps in a
 * synchronized method is as safe there as on a platform thread; before 24 it is not, and the
 * option is ignored.
 *
 * <p>The controller's code sees its own {@code Thread} object as before: the class loader sends
 * {@code Thread.currentThread()}, {@code isInterrupted()}, {@code getState()},
 * {@code getStackTrace()} and the other thread calls of contained controller code to
 * {@link ThreadHooks}, which answer for the object from the thread that runs it ({@link #of}).
 * Trusted code ({@code --trusted}) is not rewritten that far, so it keeps platform threads. Outside
 * controller code (a stack trace, a debugger) the running thread is the virtual one, named like the
 * object; {@code jcmd PID Thread.dump_to_file} lists virtual threads, {@code jstack} does not.
 *
 * <p>It is an option, not the default, for one reason: a virtual thread holds its carrier while it
 * runs without pausing (a student's loop inside a library call that never returns) and while it
 * waits inside a class initializer, and the scheduler has one carrier per core. When every carrier
 * is held so, the other controllers cannot run, and the watchdog takes them for hung. More
 * carriers would avoid that, but then the hand-overs move between carriers and cost as much as
 * between platform threads (measured: 10 robots 190× with 256 carriers, 460× with 2).
 */
final class ThreadRunners {
    /** True when controller threads run as virtual threads in this JVM. */
    static final boolean VIRTUAL;
    /**
     * The thread running each controller thread's code, by the {@code Thread} object its code
     * knows. Weak both ways: the runner's task refers to the object, so a strong value would keep
     * every run's controller (and through it the run) for the life of the JVM.
     */
    private static final java.util.Map<Thread, java.lang.ref.WeakReference<Thread>> RUNNERS =
            java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());
    private static final Method OF_VIRTUAL;
    private static final Method NAME;
    private static final Method HANDLER;
    private static final Method UNSTARTED;
    private static final Method INHERIT;

    static {
        Method ofVirtual = null;
        Method name = null;
        Method handler = null;
        Method unstarted = null;
        Method inherit = null;
        boolean wanted = Runtime.version().feature() >= 24 && Boolean.getBoolean("kheperasim.virtualThreads");
        if (wanted) {
            try {
                ofVirtual = Thread.class.getMethod("ofVirtual");
                Class<?> builder = Class.forName("java.lang.Thread$Builder");
                name = builder.getMethod("name", String.class);
                handler = builder.getMethod("uncaughtExceptionHandler", Thread.UncaughtExceptionHandler.class);
                unstarted = builder.getMethod("unstarted", Runnable.class);
                inherit = builder.getMethod("inheritInheritableThreadLocals", boolean.class);
            } catch (ReflectiveOperationException e) {
                wanted = false;
            }
        }
        VIRTUAL = wanted;
        OF_VIRTUAL = ofVirtual;
        NAME = name;
        HANDLER = handler;
        UNSTARTED = unstarted;
        INHERIT = inherit;
    }

    private ThreadRunners() {
    }

    /**
     * The thread to start for {@code thread}: the object itself, or a virtual thread that binds
     * {@code clock} and calls its {@code run()}, passing what it throws to the object's uncaught
     * exception handler.
     *
     * @param thread a controller's thread, not started (call this on the thread that constructed it)
     * @param clock the controller's clock, bound in the runner
     * @param contained true when the controller's code is contained (its thread calls go to
     *     {@link ThreadHooks}); trusted code keeps a platform thread
     * @return the thread to start
     */
    static Thread runnerOf(Thread thread, SimClock.Clock clock, boolean contained) {
        if (!VIRTUAL || !contained) {
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
            // Made where the controller was constructed, it inherits that thread's inheritable
            // thread-locals as the Thread object did; its clock is bound by the task.
            builder = INHERIT.invoke(builder, true);
            Thread runner = (Thread) UNSTARTED.invoke(builder, task);
            RUNNERS.put(thread, new java.lang.ref.WeakReference<>(runner));
            return runner;
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("could not make a virtual thread for '" + thread.getName() + "'", e);
        }
    }

    /** @return true when {@code controller}'s code is contained: loaded and rewritten by a containing class loader */
    static boolean contained(Class<?> controller) {
        return controller.getClassLoader() instanceof org.kheperasim.sim.host.loading.ControllerClassLoader l && l.contained();
    }

    /** @return the thread that runs {@code thread}'s code: a virtual thread made for it, or itself */
    static Thread of(Thread thread) {
        if (!VIRTUAL) {
            return thread;
        }
        java.lang.ref.WeakReference<Thread> ref = RUNNERS.get(thread);
        Thread runner = ref == null ? null : ref.get();
        return runner != null ? runner : thread;
    }
}
