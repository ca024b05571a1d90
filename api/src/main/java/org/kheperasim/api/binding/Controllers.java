package org.kheperasim.api.binding;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import org.kheperasim.api.Controller;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.StepController;
import org.kheperasim.api.spi.ControllerBinding;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.spi.RobotPorts;

/**
 * The controller contract, applied the same way by every backend: how a controller class is
 * checked, constructed and asked to stop.
 *
 * <p>A controller is a {@code Thread} subclass (the Appendix's style, or
 * {@link org.kheperasim.api.Controller}). A class of another style, such as a WSU
 * {@code RobotController}, is accepted when a {@link ControllerStyle} found in the class's own
 * class loader claims it; the style wraps it into the thread the backend starts.
 */
public final class Controllers {
    private Controllers() {
    }

    /**
     * Check that {@code type} is a usable controller class.
     *
     * @param type a loaded class
     * @throws ControllerException naming the class and the fix when it is not
     */
    public static void check(Class<?> type) {
        String name = type.getName();
        if (isStep(type)) {
            if (Modifier.isAbstract(type.getModifiers())) {
                throw new ControllerException("Controller " + name + " is abstract: name a concrete subclass");
            }
            if (classicConstructor(type) == null && noArgConstructor(type) == null) {
                throw new ControllerException("Step controller " + name + " has no constructor with no parameters (or "
                        + type.getSimpleName() + "(CurrentRobotState, MessagePasser)): add one");
            }
            return;
        }
        if (!Thread.class.isAssignableFrom(type)) {
            styleOf(type).check(type);
            return;
        }
        if (Modifier.isAbstract(type.getModifiers())) {
            throw new ControllerException("Controller " + name + " is abstract: name a concrete subclass");
        }
        if (classicConstructor(type) == null
                && !(Controller.class.isAssignableFrom(type) && noArgConstructor(type) != null)) {
            throw new ControllerException("Controller " + name + " has no constructor " + type.getSimpleName()
                    + "(CurrentRobotState, MessagePasser): add one as in the Appendix"
                    + (Controller.class.isAssignableFrom(type) ? ", or a constructor with no parameters" : ""));
        }
    }

    /**
     * Construct a controller, ready to {@code start()}.
     *
     * @param type the controller class (see {@link #check})
     * @param state the robot's live state to hand it
     * @param messages its message channel
     * @return the new, not yet started controller thread (for a class of another
     *     {@link ControllerStyle}, the thread that drives it)
     * @throws ControllerException when the class is unusable or its constructor throws
     */
    public static Thread instantiate(Class<?> type, CurrentRobotState state, MessagePasser messages) {
        check(type);
        if (isStep(type)) {
            return new StepRunner(instantiateStep(type, state, messages), RobotPorts.of(state));
        }
        if (!Thread.class.isAssignableFrom(type)) {
            return styleOf(type).instantiate(type, RobotPorts.of(state), messages);
        }
        try {
            return (Thread) construct(type, state, messages);
        } catch (InvocationTargetException e) {
            throw constructorThrew(type, e.getCause());
        } catch (ExceptionInInitializerError e) {
            throw initializerThrew(type, e);
        } catch (ReflectiveOperationException e) {
            throw new ControllerException("Controller " + type.getName() + " could not be created: " + e
                    + "; make the class and its constructor public", e);
        }
    }

    /**
     * @param type a loaded class
     * @return true for a {@link StepController}: a backend may step it inline instead of starting
     *     the thread {@link #instantiate} wraps it in
     */
    public static boolean isStep(Class<?> type) {
        return StepController.class.isAssignableFrom(type);
    }

    /**
     * Construct a step controller, to be stepped inline by the backend.
     *
     * @param type a {@link StepController} class (see {@link #check})
     * @param state the robot's live state to hand it
     * @param messages its message channel
     * @return the controller
     * @throws ControllerException when the class is unusable or its constructor throws
     */
    public static StepController instantiateStep(Class<?> type, CurrentRobotState state, MessagePasser messages) {
        check(type);
        try {
            return (StepController) construct(type, state, messages);
        } catch (InvocationTargetException e) {
            throw constructorThrew(type, e.getCause());
        } catch (ExceptionInInitializerError e) {
            throw initializerThrew(type, e);
        } catch (ReflectiveOperationException e) {
            throw new ControllerException("Controller " + type.getName() + " could not be created: " + e
                    + "; make the class and its constructor public", e);
        }
    }

    /**
     * The classic constructor {@code (CurrentRobotState, MessagePasser)} when the class has one, else the
     * one with no parameters, with the state bound to this thread while it runs ({@link ControllerBinding}).
     */
    private static Object construct(Class<?> type, CurrentRobotState state, MessagePasser messages)
            throws ReflectiveOperationException {
        Constructor<?> classic = classicConstructor(type);
        if (classic != null) {
            return classic.newInstance(state, messages);
        }
        ControllerBinding.bind(new ControllerBinding(state, messages));
        try {
            return noArgConstructor(type).newInstance();
        } finally {
            ControllerBinding.bind(null);
        }
    }

    /**
     * Ask a running controller to stop the way the Appendix expects: call its public, parameterless
     * {@code killControl()} when it has one.
     *
     * @param controller the controller thread
     * @return true when a {@code killControl()} was found and called
     */
    public static boolean requestStop(Thread controller) {
        Method kill;
        try {
            kill = controller.getClass().getMethod("killControl");
        } catch (NoSuchMethodException e) {
            return false;
        }
        try {
            kill.setAccessible(true);
            kill.invoke(controller);
            return true;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return false;
        }
    }

    /**
     * End a {@link Controller}'s {@code doWork()} loop after the current round, as its
     * {@code killControl()} does, without calling any of the controller's code: a field written, so
     * the simulator may do it from its own threads (a {@code doWork()} that returns at once without a
     * robot call never reaches a point where the controller's own thread could be asked). Its own
     * {@code killControl()}, if it overrides it, is the controller's thread's to call.
     *
     * @param controller a controller's thread; nothing happens when it is not a {@link Controller}
     */
    public static void endDoWorkLoop(Thread controller) {
        if (!(controller instanceof Controller)) {
            return;
        }
        try {
            ACTIVE.setBoolean(controller, false);
        } catch (ReflectiveOperationException | RuntimeException e) {
            // Cannot happen for the API's own field; the controller's thread is asked at its next call.
        }
    }

    private static final java.lang.reflect.Field ACTIVE = activeField();

    private static java.lang.reflect.Field activeField() {
        try {
            java.lang.reflect.Field f = Controller.class.getDeclaredField("active");
            f.setAccessible(true);
            return f;
        } catch (NoSuchFieldException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /**
     * How many times a {@link Controller}'s {@code doWork()} has returned so far, for telling a
     * {@code doWork()} that keeps returning without a robot call (no simulated time passes) from one
     * that loops inside.
     *
     * @param controller a controller's thread
     * @return the count, or -1 when it is not a {@link Controller}
     */
    public static long doWorkRounds(Thread controller) {
        if (!(controller instanceof Controller)) {
            return -1;
        }
        try {
            java.lang.reflect.Field f = Controller.class.getDeclaredField("rounds");
            f.setAccessible(true);
            return f.getLong(controller);
        } catch (ReflectiveOperationException | RuntimeException e) {
            return -1;
        }
    }

    /**
     * The {@link ControllerStyle} that claims a class which does not extend {@code Thread}, looked
     * up in the class's own loader so that the style and the class share their base classes.
     *
     * @throws ControllerException naming the class and every style it could have followed
     */
    private static ControllerStyle styleOf(Class<?> type) {
        List<String> known = new ArrayList<>();
        List<String> broken = new ArrayList<>();
        ClassLoader loader = type.getClassLoader() != null ? type.getClassLoader() : ClassLoader.getSystemClassLoader();
        Iterator<ControllerStyle> styles = ServiceLoader.load(ControllerStyle.class, loader).iterator();
        while (true) {
            ControllerStyle style;
            try {
                if (!styles.hasNext()) {
                    break;
                }
                style = styles.next();
            } catch (ServiceConfigurationError e) {
                broken.add(String.valueOf(e.getMessage()));
                continue;
            }
            if (style.claims(type)) {
                return style;
            }
            known.add(style.describe());
        }
        StringBuilder ways = new StringBuilder("a Thread subclass (as in the Appendix: 'public class Robot extends"
                + " Thread'), or extends org.kheperasim.api.Controller or org.kheperasim.api.StepController");
        for (String way : known) {
            ways.append(", or ").append(way);
        }
        throw new ControllerException("Controller " + type.getName() + " does not extend Thread: a controller is "
                + ways + (broken.isEmpty() ? "" : " (a controller style could not be loaded: "
                + String.join("; ", broken) + ")"));
    }

    /**
     * A class's two kinds of controller constructor, {classic, no parameters} (null where it has none),
     * looked up once per class: an evaluation constructs the same class thousands of times, and a
     * lookup that finds nothing costs an exception.
     */
    private static final ClassValue<Constructor<?>[]> CONSTRUCTORS = new ClassValue<>() {
        @Override
        protected Constructor<?>[] computeValue(Class<?> type) {
            return new Constructor<?>[] {accessible(type, CurrentRobotState.class, MessagePasser.class),
                    accessible(type)};
        }
    };

    private static Constructor<?> classicConstructor(Class<?> type) {
        return CONSTRUCTORS.get(type)[0];
    }

    private static Constructor<?> noArgConstructor(Class<?> type) {
        return CONSTRUCTORS.get(type)[1];
    }

    private static Constructor<?> accessible(Class<?> type, Class<?>... parameters) {
        try {
            Constructor<?> c = type.getDeclaredConstructor(parameters);
            c.setAccessible(true);
            return c;
        } catch (NoSuchMethodException | RuntimeException e) {
            return null;
        }
    }

    /**
     * @param type a controller class
     * @param cause what its constructor threw
     * @return the error for the user: what was thrown, where in the controller's code, and the fix
     */
    public static ControllerException constructorThrew(Class<?> type, Throwable cause) {
        return new ControllerException("The constructor of controller " + type.getName() + " threw " + cause
                + where(type, cause) + "; fix the constructor", cause);
    }

    /**
     * @param type a controller class
     * @param e what initialising it threw
     * @return the error for the user, as {@link #constructorThrew}
     */
    public static ControllerException initializerThrew(Class<?> type, ExceptionInInitializerError e) {
        Throwable cause = e.getCause() != null ? e.getCause() : e;
        return new ControllerException("A static initializer of controller " + type.getName() + " threw " + cause
                + where(type, cause) + "; fix the initialization of its static fields", cause);
    }

    /** @return where in the controller's own code {@code t} was thrown, e.g. " at Avoider.java:12", or "" */
    private static String where(Class<?> type, Throwable t) {
        for (StackTraceElement e : t.getStackTrace()) {
            String cls = e.getClassName();
            if (cls.equals(type.getName()) || cls.startsWith(type.getName() + "$")) {
                return e.getFileName() == null ? " in " + cls + "." + e.getMethodName()
                        : " at " + e.getFileName() + ":" + e.getLineNumber();
            }
        }
        return "";
    }
}
