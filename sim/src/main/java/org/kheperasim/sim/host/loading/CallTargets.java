package org.kheperasim.sim.host.loading;

import java.util.Set;
import org.kheperasim.sim.host.SimClock;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * Where a call in controller code goes instead: the time calls to {@link SimClock} (and the
 * wall-clock reads of {@code java.util} to {@link CalendarHooks}), and for
 * contained code the escapes to {@link org.kheperasim.sim.host.Containment}, the thread calls to
 * {@link org.kheperasim.sim.host.ThreadHooks}, {@code wait}, {@code notify}, {@code notifyAll} and
 * {@code Thread.holdsLock} to {@link MonitorHooks} (each robot's own monitors), the resource reads to
 * {@link ResourceHooks},
 * {@code printStackTrace()} and {@code Logger.getLogger} to {@link ConsoleHooks}, and the parallel
 * stream methods to their sequential twins (see {@link TimeCallRewriter} for what is rewritten and
 * why).
 */
final class CallTargets {
    /** Internal name of the class the time calls go to. */
    static final String SIM_CLOCK = Type.getInternalName(SimClock.class);
    private static final String THREAD = "java/lang/Thread";
    private static final String SYSTEM = "java/lang/System";
    private static final String TIME_UNIT = "java/util/concurrent/TimeUnit";

    /** The static methods of {@code Thread} that {@link SimClock} replaces, as name + descriptor. */
    private static final Set<String> THREAD_STATICS = Set.of(
            "sleep(J)V", "sleep(JI)V", "sleep(Ljava/time/Duration;)V", "yield()V", "onSpinWait()V");

    /** The static methods of {@code System} that {@link SimClock} replaces, as name + descriptor. */
    private static final Set<String> SYSTEM_STATICS = Set.of("currentTimeMillis()J", "nanoTime()J");

    /** The class {@code Calendar.getInstance} goes to, and the overloads it replaces (name + descriptor). */
    static final String CALENDAR_HOOKS = Type.getInternalName(CalendarHooks.class);
    private static final String CALENDAR = "java/util/Calendar";
    private static final Set<String> CALENDAR_STATICS = Set.of("getInstance()Ljava/util/Calendar;",
            "getInstance(Ljava/util/TimeZone;)Ljava/util/Calendar;",
            "getInstance(Ljava/util/Locale;)Ljava/util/Calendar;",
            "getInstance(Ljava/util/TimeZone;Ljava/util/Locale;)Ljava/util/Calendar;");

    /**
     * The constructors of {@code java.util} that read the wall clock, by owner + descriptor: the
     * parameter type of the {@link CalendarHooks} method that sets the new object to the simulated
     * clock, and of the factory a constructor reference goes to instead.
     */
    private static final java.util.Map<String, String> CLOCK_CONSTRUCTORS = java.util.Map.of(
            "java/util/GregorianCalendar()V", "Ljava/util/Calendar;",
            "java/util/GregorianCalendar(Ljava/util/TimeZone;)V", "Ljava/util/Calendar;",
            "java/util/GregorianCalendar(Ljava/util/Locale;)V", "Ljava/util/Calendar;",
            "java/util/GregorianCalendar(Ljava/util/TimeZone;Ljava/util/Locale;)V", "Ljava/util/Calendar;",
            "java/util/Date()V", "Ljava/util/Date;");

    /** The replacement of the instance method {@code TimeUnit.sleep(long)}: the unit comes first. */
    private static final String TIME_UNIT_SLEEP_HOOK = "(L" + TIME_UNIT + ";J)V";

    /** Internal name of the class the containment hooks are in. */
    static final String CONTAINMENT = Type.getInternalName(org.kheperasim.sim.host.Containment.class);

    /** Internal name of the class the thread hooks are in. */
    static final String THREAD_HOOKS = Type.getInternalName(org.kheperasim.sim.host.ThreadHooks.class);

    /** Instance methods of {@code Thread} (or a subclass) that {@link org.kheperasim.sim.host.ThreadHooks} replaces. */
    private static final java.util.Map<String, String> THREAD_VIRTUALS = java.util.Map.of(
            "start()V", "start", "join()V", "join", "join(J)V", "join", "join(JI)V", "join",
            "isAlive()Z", "isAlive", "interrupt()V", "interrupt", "isInterrupted()Z", "isInterrupted",
            "getState()Ljava/lang/Thread$State;", "getState", "getStackTrace()[Ljava/lang/StackTraceElement;",
            "getStackTrace");

    /**
     * The methods of {@code Thread} whose {@code super} calls (from a subclass that overrides them)
     * {@link org.kheperasim.sim.host.ThreadHooks} replaces: the override is the student's, the
     * start or interrupt it asks of {@code Thread} the lockstep's.
     */
    private static final java.util.Map<String, String> THREAD_SUPERS = java.util.Map.of(
            "start()V", "superStart", "interrupt()V", "superInterrupt");

    /** {@code Thread.currentThread()}, which {@link org.kheperasim.sim.host.ThreadHooks} answers for contained code. */
    private static final String CURRENT_THREAD = "currentThread()Ljava/lang/Thread;";

    /**
     * Static calls redirected to {@link org.kheperasim.sim.host.Containment}, by owner, name and
     * descriptor, to the method of the given name and the same descriptor.
     */
    private static final java.util.Map<String, String> CONTAINED_STATICS = java.util.Map.ofEntries(
            java.util.Map.entry("java/lang/System.exit(I)V", "exit"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.parkNanos(J)V", "parkNanos"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.parkNanos(Ljava/lang/Object;J)V", "parkNanos"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.parkUntil(J)V", "parkUntil"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.parkUntil(Ljava/lang/Object;J)V", "parkUntil"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.park()V", "park"),
            java.util.Map.entry("java/util/concurrent/locks/LockSupport.park(Ljava/lang/Object;)V", "park"),
            java.util.Map.entry("java/time/Instant.now()Ljava/time/Instant;", "instantNow"),
            java.util.Map.entry("java/time/Clock.systemUTC()Ljava/time/Clock;", "clockUTC"),
            java.util.Map.entry("java/time/Clock.systemDefaultZone()Ljava/time/Clock;", "clockDefaultZone"),
            java.util.Map.entry("java/time/LocalDateTime.now()Ljava/time/LocalDateTime;", "localDateTimeNow"),
            java.util.Map.entry("java/time/LocalDate.now()Ljava/time/LocalDate;", "localDateNow"),
            java.util.Map.entry("java/time/LocalTime.now()Ljava/time/LocalTime;", "localTimeNow"),
            java.util.Map.entry("java/time/ZonedDateTime.now()Ljava/time/ZonedDateTime;", "zonedDateTimeNow"));

    /** Internal name of the class the resource hooks are in. */
    private static final String RESOURCES = Type.getInternalName(ResourceHooks.class);

    /** Internal name of the class the console hooks are in. */
    private static final String CONSOLE = Type.getInternalName(ConsoleHooks.class);

    /**
     * Instance calls redirected to static hooks that take the receiver first, by owner, name and
     * descriptor, to the hook's class and name.
     */
    private static final java.util.Map<String, String[]> CONTAINED_VIRTUALS = java.util.Map.of(
            "java/lang/Runtime.exit(I)V", new String[] {CONTAINMENT, "exit"},
            "java/lang/Runtime.halt(I)V", new String[] {CONTAINMENT, "halt"},
            "java/lang/Runtime.addShutdownHook(Ljava/lang/Thread;)V", new String[] {CONTAINMENT, "addShutdownHook"},
            "java/lang/Class.getResource(Ljava/lang/String;)Ljava/net/URL;", new String[] {RESOURCES, "getResource"},
            "java/lang/Class.getResourceAsStream(Ljava/lang/String;)Ljava/io/InputStream;",
            new String[] {RESOURCES, "getResourceAsStream"},
            "java/lang/ClassLoader.getResource(Ljava/lang/String;)Ljava/net/URL;",
            new String[] {RESOURCES, "getResource"},
            "java/lang/ClassLoader.getResourceAsStream(Ljava/lang/String;)Ljava/io/InputStream;",
            new String[] {RESOURCES, "getResourceAsStream"});

    /** {@code Logger.getLogger(String)}, which {@link ConsoleHooks} answers with a logger of the run's own. */
    private static final String GET_LOGGER =
            "java/util/logging/Logger.getLogger(Ljava/lang/String;)Ljava/util/logging/Logger;";

    private static final String THROWABLE = "java/lang/Throwable";
    private static final String PRINT_STACK_TRACE = "printStackTrace()V";

    /**
     * Methods of parallel streams, by declaring class, name and descriptor: the sequential method of the same
     * descriptor.
     */
    private static final java.util.Map<String, String> SEQUENTIAL = java.util.Map.of(
            "java/util/Collection.parallelStream()Ljava/util/stream/Stream;", "stream",
            "java/util/stream/BaseStream.parallel()Ljava/util/stream/BaseStream;", "sequential",
            "java/util/stream/IntStream.parallel()Ljava/util/stream/IntStream;", "sequential",
            "java/util/stream/LongStream.parallel()Ljava/util/stream/LongStream;", "sequential",
            "java/util/stream/DoubleStream.parallel()Ljava/util/stream/DoubleStream;", "sequential");

    private final HierarchyLookup lookup;
    private final boolean contained;

    /** Internal name of the class the monitor hooks are in. */
    static final String MONITOR_HOOKS = Type.getInternalName(MonitorHooks.class);

    /** {@code Thread.holdsLock(Object)}, which {@link MonitorHooks} answers for the robot's own monitor. */
    private static final String HOLDS_LOCK = "holdsLock(Ljava/lang/Object;)Z";

    /**
     * Where a call goes instead.
     *
     * @param caller true when the hook also takes the calling class, last ({@link #descriptorWithCaller()});
     *     {@link #descriptor()} is then that of its form without it (for a method handle)
     */
    record Target(String owner, String name, String descriptor, boolean caller) {
        Target(String owner, String name, String descriptor) {
            this(owner, name, descriptor, false);
        }

        /** @return the descriptor of the form that takes the calling class last */
        String descriptorWithCaller() {
            int close = descriptor.indexOf(')');
            return descriptor.substring(0, close) + "Ljava/lang/Class;" + descriptor.substring(close);
        }
    }

    CallTargets(HierarchyLookup lookup, boolean contained) {
        this.lookup = lookup;
        this.contained = contained;
    }

    /**
     * Where a call goes instead, or null when it stays: the {@link SimClock} method of the same
     * name for the time calls, and for contained code the hooks (see the class comment).
     *
     * @param opcode {@link Opcodes#INVOKESTATIC}, {@link Opcodes#INVOKEVIRTUAL} or
     *     {@link Opcodes#INVOKESPECIAL} (only {@code super.start()} and {@code super.interrupt()} of
     *     {@code Thread} move); any other kind of call always stays
     */
    Target of(int opcode, String owner, String name, String descriptor) {
        if (opcode == Opcodes.INVOKESTATIC) {
            String method = name + descriptor;
            if (THREAD_STATICS.contains(method)
                    && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                return new Target(SIM_CLOCK, name, descriptor);
            }
            if (owner.equals(SYSTEM) && SYSTEM_STATICS.contains(method)) {
                return new Target(SIM_CLOCK, name, descriptor);
            }
            if (CALENDAR_STATICS.contains(method)
                    && (owner.equals(CALENDAR) || CALENDAR.equals(lookup.declaringClass(owner, name, descriptor)))) {
                return new Target(CALENDAR_HOOKS, name, descriptor);
            }
            if (contained && method.equals(HOLDS_LOCK)
                    && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                return new Target(MONITOR_HOOKS, "holdsLock", descriptor, true);
            }
            if (contained && method.equals(CURRENT_THREAD)
                    && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                return new Target(THREAD_HOOKS, name, descriptor);
            }
            String contain = contained ? CONTAINED_STATICS.get(owner + "." + method) : null;
            if (contain != null) {
                return new Target(CONTAINMENT, contain, descriptor);
            }
            if (contained && GET_LOGGER.equals(owner + "." + method)) {
                return new Target(CONSOLE, name, descriptor);
            }
        } else if (opcode == Opcodes.INVOKESPECIAL) {
            // super.start() and super.interrupt() in a Thread subclass's own override: the lockstep's too.
            String hook = contained ? THREAD_SUPERS.get(name + descriptor) : null;
            if (hook != null && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                return new Target(THREAD_HOOKS, hook, "(Ljava/lang/Thread;)V");
            }
        } else if (opcode == Opcodes.INVOKEVIRTUAL) {
            if (owner.equals(TIME_UNIT) && name.equals("sleep") && descriptor.equals("(J)V")) {
                return new Target(SIM_CLOCK, name, TIME_UNIT_SLEEP_HOOK);
            }
            if (!contained) {
                return null;
            }
            String[] contain = CONTAINED_VIRTUALS.get(owner + "." + name + descriptor);
            if (contain != null) {
                return new Target(contain[0], contain[1], "(L" + owner + ";" + descriptor.substring(1));
            }
            if (owner.startsWith("[")) {
                return null;
            }
            if ((name + descriptor).equals(PRINT_STACK_TRACE)
                    && (owner.equals(THROWABLE) || THROWABLE.equals(lookup.declaringClass(owner, name, descriptor)))) {
                return new Target(CONSOLE, name, "(L" + THROWABLE + ";)V");
            }
            String receiver = "(Ljava/lang/Object;";
            switch (name + descriptor) {
                case "wait()V" -> {
                    return new Target(MONITOR_HOOKS, "waitForever", receiver + ")V", true);
                }
                case "wait(J)V", "wait(JI)V" -> {
                    return new Target(MONITOR_HOOKS, "waitFor", receiver + descriptor.substring(1), true);
                }
                case "notify()V", "notifyAll()V" -> {
                    return new Target(MONITOR_HOOKS, name, receiver + ")V", true);
                }
                default -> {
                    // a thread call, below
                }
            }
            String hook = THREAD_VIRTUALS.get(name + descriptor);
            if (hook != null && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                return new Target(THREAD_HOOKS, hook, "(Ljava/lang/Thread;" + descriptor.substring(1));
            }
        }
        return null;
    }

    /** @return true when {@code owner} has a constructor that reads the wall clock (see {@link #afterConstructor}) */
    static boolean readsTheClockWhenMade(String owner) {
        return owner.equals("java/util/GregorianCalendar") || owner.equals("java/util/Date");
    }

    /**
     * The hook to call on an object just made by a constructor that reads the wall clock
     * ({@code new GregorianCalendar()}, {@code new Date()}, or a subclass's {@code super()} of one),
     * which sets it to the simulated clock; null for any other constructor.
     *
     * @param owner the class whose constructor is called (the owner of the {@code invokespecial})
     * @param descriptor the constructor's descriptor
     */
    Target afterConstructor(String owner, String descriptor) {
        String type = CLOCK_CONSTRUCTORS.get(owner + descriptor);
        return type == null ? null : new Target(CALENDAR_HOOKS, "simulatedNow", "(" + type + ")V");
    }

    /**
     * Where a constructor reference ({@code GregorianCalendar::new}, {@code Date::new}) to a
     * constructor that reads the wall clock goes instead: a {@link CalendarHooks} factory of the same
     * parameters that returns the object set to the simulated clock; null for any other constructor.
     */
    Target constructorReference(String owner, String descriptor) {
        if (!CLOCK_CONSTRUCTORS.containsKey(owner + descriptor)) {
            return null;
        }
        String name = owner.equals("java/util/Date") ? "newDate" : "newGregorianCalendar";
        return new Target(CALENDAR_HOOKS, name, descriptor.substring(0, descriptor.length() - 1) + "L" + owner + ";");
    }

    /**
     * The sequential twin of a parallel stream method, for contained code: {@code parallel()}
     * becomes {@code sequential()} and {@code Collection.parallelStream()} {@code stream()}, with the
     * same owner and descriptor. A parallel stream would run the controller's lambdas on the JDK's
     * common pool, outside the lockstep; running it on the calling thread is one of the executions a
     * parallel stream allows, so every correct stream computes the same.
     *
     * @return the method's new name, or null when the call stays
     */
    String renamed(String owner, String name, String descriptor) {
        if (!contained || owner.startsWith("[") || !(name.equals("parallel") || name.equals("parallelStream"))) {
            return null;
        }
        String sequential = SEQUENTIAL.get(owner + "." + name + descriptor);
        if (sequential != null) {
            return sequential;
        }
        String declaring = lookup.declaringClass(owner, name, descriptor);
        return declaring == null ? null : SEQUENTIAL.get(declaring + "." + name + descriptor);
    }
}
