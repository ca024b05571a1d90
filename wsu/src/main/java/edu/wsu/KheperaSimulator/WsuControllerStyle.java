package edu.wsu.KheperaSimulator;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.binding.ControllerStyle;
import org.kheperasim.api.spi.RobotPort;

/**
 * Lets every backend run a controller written for the WSU Khepera Simulator: a subclass of
 * {@link RobotController} with a constructor without parameters. Registered in
 * {@code META-INF/services/org.kheperasim.api.binding.ControllerStyle}, so
 * {@code org.kheperasim.api.binding.Controllers} finds it; nothing else calls it.
 *
 * <p>Creating a controller does what the original did: construct it, then
 * {@code initialize(simpleName, state, 20)}. The thread returned calls its {@code simStart()} and runs
 * its loop over the backend's {@link RobotPort}.
 */
public final class WsuControllerStyle implements ControllerStyle {
    private static final String BASE = RobotController.class.getName();

    /** For {@link java.util.ServiceLoader}. */
    public WsuControllerStyle() {
    }

    @Override
    public String describe() {
        return "extends " + BASE + " (a controller written for the WSU Khepera Simulator)";
    }

    @Override
    public boolean claims(Class<?> type) {
        return Controller.class.isAssignableFrom(type);
    }

    @Override
    public void check(Class<?> type) {
        String name = type.getName();
        if (!RobotController.class.isAssignableFrom(type)) {
            throw new ControllerException("Controller " + name + " implements " + Controller.class.getName()
                    + " but does not extend " + BASE + ": write 'public class " + type.getSimpleName()
                    + " extends RobotController', which runs doWork() and close() for it");
        }
        if (Modifier.isAbstract(type.getModifiers())) {
            throw new ControllerException("Controller " + name + " is abstract: name a concrete subclass");
        }
        if (noArgConstructor(type) == null) {
            throw new ControllerException("Controller " + name + " has no constructor without parameters: add 'public "
                    + type.getSimpleName() + "() { }' (the WSU simulator creates controllers that way)"
                    + (type.getEnclosingClass() != null && !Modifier.isStatic(type.getModifiers())
                    ? ", and make the class static or move it to its own file" : ""));
        }
    }

    @Override
    public Thread instantiate(Class<?> type, RobotPort port, MessagePasser messages) {
        check(type);
        RobotController controller;
        RobotController.BACKEND_CREATING.set(Boolean.TRUE);
        try {
            controller = (RobotController) noArgConstructor(type).newInstance();
        } catch (InvocationTargetException e) {
            throw org.kheperasim.api.binding.Controllers.constructorThrew(type, e.getCause());
        } catch (ExceptionInInitializerError e) {
            throw org.kheperasim.api.binding.Controllers.initializerThrew(type, e);
        } catch (ReflectiveOperationException e) {
            throw new ControllerException("Controller " + type.getName() + " could not be created: " + e
                    + "; make the class and its constructor public", e);
        } finally {
            RobotController.BACKEND_CREATING.remove();
        }
        String name = type.getSimpleName();
        CurrentRobotState state = new CurrentRobotState(port);
        controller.initialize(name, state, RobotController.SIMULATOR_WAIT_MS);
        RobotControllerThread runner = new RobotControllerThread(controller, state, name);
        controller.attach(runner);
        return runner;
    }

    private static Constructor<?> noArgConstructor(Class<?> type) {
        try {
            Constructor<?> c = type.getDeclaredConstructor();
            c.setAccessible(true);
            return c;
        } catch (NoSuchMethodException | RuntimeException e) {
            return null;
        }
    }
}
