package org.kheperasim.api.binding;

import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.spi.RobotPort;

/**
 * Another style of controller class than the contract's {@code Thread} subclass, for example the
 * {@code RobotController} of the original WSU Khepera Simulator. A style wraps such a class into a
 * {@link Thread} that drives it over the robot's {@link RobotPort}, so every backend runs it the
 * way it runs any controller: {@link Controllers#check}, {@link Controllers#instantiate},
 * {@code start()}, and {@link Controllers#requestStop} (which calls the thread's public
 * {@code killControl()} when it has one).
 *
 * <p>Styles are found with {@link java.util.ServiceLoader} in the class loader of the controller
 * class being checked (a module lists its implementation in
 * {@code META-INF/services/org.kheperasim.api.binding.ControllerStyle}), so the style sees the same
 * base classes as the controller, whichever loader defined it. An implementation needs a public
 * constructor without parameters, and must not initialise the classes it is asked about.
 */
public interface ControllerStyle {

    /**
     * @return how this style's controllers are recognised, for the error about a class that fits
     *     no style, e.g. {@code "extends edu.wsu.KheperaSimulator.RobotController"}
     */
    String describe();

    /**
     * @param type a loaded class that does not extend {@code Thread}
     * @return whether the class belongs to this style (then {@link #check} decides whether it is usable)
     */
    boolean claims(Class<?> type);

    /**
     * Check that a class this style {@linkplain #claims claims} is a usable controller.
     *
     * @param type the class
     * @throws ControllerException naming the class, what is wrong and the fix
     */
    void check(Class<?> type);

    /**
     * Construct the controller and the thread that runs it. Called on the backend's thread; the
     * returned thread must be constructed here (a backend may hand state to it through inheritable
     * thread-locals bound during this call).
     *
     * @param type a class that passed {@link #check}
     * @param port the robot behind the controller (units as in {@link RobotPort})
     * @param messages the controller's message channel
     * @return the new, not yet started thread; ending its {@code run()} ends the controller, and an
     *     exception thrown by the controller leaves {@code run()} unchanged, for the backend to report
     * @throws ControllerException when the controller cannot be constructed (its constructor throws)
     */
    Thread instantiate(Class<?> type, RobotPort port, MessagePasser messages);
}
