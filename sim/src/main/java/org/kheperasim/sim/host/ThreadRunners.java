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
 * too; between virtual threads it is a switch on the same carrier (under 1 µs). From Java 24 on a virtual thread that
 * waits inside {@code synchronized} code no longer holds its carrier (JEP 491), so student code that sleeps in a
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
 *
 * <p>A contained controller's thread whose class overrides a method of {@code Thread} or
 * {@code Object} besides {@code run()} ({@code interrupt}, {@code start}, {@code getState},
 * {@code getUncaughtExceptionHandler}, {@code toString}, {@code hashCode}, ...) runs on a platform
 * thread of the simulator's own ({@link Runner}) that calls the object's {@code run()}: the
 * simulator starts, interrupts and watches that thread, and learns how the code ended from it, so
 * it never calls the student's overrides, on its threads or anywhere (an override that spins, throws
 * or blocks changes nothing; the controller runs as one without it). The object itself is never
 * started; the thread calls of its code are answered for it as for a virtual runner. Such a
 * runner has the default stack size (a size asked of the object's constructor is not honoured).
 */
final class ThreadRunners {
    /** True when controller threads run as virtual threads in this JVM. */
    static final boolean VIRTUAL;
    /**
     * The thread running each controller thread's code, by the {@code Thread} object its code
     * knows, where that is another thread. By identity, never by the object's {@code hashCode} or
     * {@code equals} (the student's to override); weak both ways: the runner's task refers to the
     * object, so a strong value would keep every run's controller (and through it the run) for the
     * life of the JVM.
     */
    private static final IdentityRunners RUNNERS = new IdentityRunners();
    private static final Method OF_VIRTUAL;
    private static final Method NAME;
    private static final Method UNSTARTED;
    private static final Method INHERIT;

    static {
        Method ofVirtual = null;
        Method name = null;
        Method unstarted = null;
        Method inherit = null;
        boolean wanted = Runtime.version().feature() >= 24 && Boolean.getBoolean("kheperasim.virtualThreads");
        if (wanted) {
            try {
                ofVirtual = Thread.class.getMethod("ofVirtual");
                Class<?> builder = Class.forName("java.lang.Thread$Builder");
                name = builder.getMethod("name", String.class);
                unstarted = builder.getMethod("unstarted", Runnable.class);
                inherit = builder.getMethod("inheritInheritableThreadLocals", boolean.class);
            } catch (ReflectiveOperationException e) {
                wanted = false;
            }
        }
        VIRTUAL = wanted;
        OF_VIRTUAL = ofVirtual;
        NAME = name;
        UNSTARTED = unstarted;
        INHERIT = inherit;
    }

    private ThreadRunners() {
    }

    /**
     * The thread to start for {@code thread}, made ready: the object itself (daemon, {@code handler}
     * its uncaught-exception handler); or a thread that binds {@code clock}, calls the object's
     * {@code run()} and passes what that throws to {@code handler}: a virtual thread for the
     * controller's own thread when {@link #VIRTUAL}, a {@link Runner} for a contained thread whose
     * class overrides {@code Thread}'s methods (see the class comment).
     *
     * @param thread a controller's thread, not started (call this on the thread that made or starts it)
     * @param clock the controller's clock, bound in the runner
     * @param contained true when the controller's code is contained (its thread calls go to
     *     {@link ThreadHooks}); trusted code keeps its own threads
     * @param own true for the controller's own thread, false for one its code started
     * @param handler told what the thread's code threw
     * @return the thread to start
     */
    static Thread runnerOf(Thread thread, SimClock.Clock clock, boolean contained, boolean own,
            Thread.UncaughtExceptionHandler handler) {
        boolean virtual = VIRTUAL && contained && own;
        if (!virtual && !(contained && overrides(thread.getClass()))) {
            thread.setDaemon(true);
            thread.setUncaughtExceptionHandler(handler);
            return thread;
        }
        Runnable task = () -> {
            SimClock.bind(clock);
            try {
                thread.run();
            } catch (Throwable e) {
                handler.uncaughtException(thread, e);
            }
        };
        Thread runner = virtual ? virtual(thread, task) : new Runner(thread, task);
        RUNNERS.put(thread, runner);
        return runner;
    }

    /**
     * The thread to start for a thread the controller's code starts outside the lockstep (see
     * {@link StrayThreads}), made ready as {@link #runnerOf} does; on the thread that starts it. Its
     * runner binds no clock: it inherits the starting thread's, as the object did.
     */
    static Thread strayRunner(Thread thread, boolean contained, Thread.UncaughtExceptionHandler handler) {
        if (!(contained && overrides(thread.getClass()))) {
            thread.setDaemon(true);
            thread.setUncaughtExceptionHandler(handler);
            return thread;
        }
        Thread runner = new Runner(thread, () -> {
            try {
                thread.run();
            } catch (Throwable e) {
                handler.uncaughtException(thread, e);
            }
        });
        RUNNERS.put(thread, runner);
        return runner;
    }

    private static Thread virtual(Thread thread, Runnable task) {
        try {
            Object builder = OF_VIRTUAL.invoke(null);
            builder = NAME.invoke(builder, thread.getName());
            // Made where the controller was constructed, it inherits that thread's inheritable
            // thread-locals as the Thread object did; its clock is bound by the task.
            builder = INHERIT.invoke(builder, true);
            return (Thread) UNSTARTED.invoke(builder, task);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("could not make a virtual thread for '" + thread.getName() + "'", e);
        }
    }

    /**
     * A platform thread of the simulator's that runs a controller thread's code: a final class
     * overriding nothing, so whatever the simulator asks of it is the JDK's answer. It is named
     * like the object and has its priority; made on the thread that starts (or, for the
     * controller's own thread, constructed) the object, it inherits that thread's inheritable
     * thread-locals.
     */
    static final class Runner extends Thread {
        /** The {@code Thread} object whose code it runs. */
        final Thread object;

        Runner(Thread object, Runnable task) {
            super(null, task, object.getName(), 0, true);
            this.object = object;
            setDaemon(true);
            setPriority(object.getPriority());
            // The task passes every throwable on; one thrown by that hand-over itself ends this thread quietly.
            setUncaughtExceptionHandler((t, e) -> { });
        }
    }

    /**
     * Does {@code type} override a method of {@code Thread} or {@code Object} that can be
     * overridden (public or protected, not final, not static), besides {@code run()}? Looked at
     * once per class, in the classes between it and {@code Thread}.
     */
    static boolean overrides(Class<?> type) {
        return OVERRIDES.get(type);
    }

    /** @return true when {@code type}'s {@code interrupt()} is not {@code Thread}'s own */
    static boolean overridesInterrupt(Class<?> type) {
        return OVERRIDES_INTERRUPT.get(type);
    }

    private static final ClassValue<Boolean> OVERRIDES_INTERRUPT = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            try {
                return type.getMethod("interrupt").getDeclaringClass() != Thread.class;
            } catch (NoSuchMethodException e) {
                return false;
            }
        }
    };

    private static final ClassValue<Boolean> OVERRIDES = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            for (Class<?> c = type; c != null && c != Thread.class && c != Object.class; c = c.getSuperclass()) {
                for (Method m : c.getDeclaredMethods()) {
                    int mod = m.getModifiers();
                    if (java.lang.reflect.Modifier.isStatic(mod) || java.lang.reflect.Modifier.isPrivate(mod)
                            || m.isSynthetic() || m.getName().equals("run") && m.getParameterCount() == 0) {
                        continue;
                    }
                    if (overridable(m)) {
                        return true;
                    }
                }
            }
            return false;
        }

        private boolean overridable(Method m) {
            for (Class<?> c = Thread.class; c != null; c = c.getSuperclass()) {
                try {
                    Method base = c.getDeclaredMethod(m.getName(), m.getParameterTypes());
                    int mod = base.getModifiers();
                    return !java.lang.reflect.Modifier.isFinal(mod) && !java.lang.reflect.Modifier.isStatic(mod)
                            && (java.lang.reflect.Modifier.isPublic(mod)
                                    || java.lang.reflect.Modifier.isProtected(mod));
                } catch (NoSuchMethodException e) {
                    // not declared there; look in its superclass
                }
            }
            return false;
        }
    };

    /** @return true when {@code controller}'s code is contained: loaded and rewritten by a containing class loader */
    static boolean contained(Class<?> controller) {
        return controller.getClassLoader() instanceof ContainingLoader l && l.contained();
    }

    /** @return the thread that runs {@code thread}'s code: a thread made for it, or itself */
    static Thread of(Thread thread) {
        Thread runner = RUNNERS.get(thread);
        return runner != null ? runner : thread;
    }

    /**
     * @return true when {@code t} was started: by the simulator (a thread runs its code), or by
     *     itself. Asked of the object only where its {@code getState()} is the JDK's.
     */
    static boolean started(Thread t) {
        return overrides(t.getClass()) ? of(t) != t || t.isAlive() : t.getState() != Thread.State.NEW;
    }

    /**
     * @return the {@code Thread} object whose code {@code running} runs: the object of a {@link Runner}, else itself
     */
    static Thread objectOf(Thread running) {
        return running instanceof Runner r ? r.object : running;
    }
}
