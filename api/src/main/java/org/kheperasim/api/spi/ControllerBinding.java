package org.kheperasim.api.spi;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Hands the robot's state to a {@link org.kheperasim.api.Controller} subclass that declares no
 * constructor: the backend binds the state to the creating thread while the constructor runs.
 *
 * @param state the robot's live state
 * @param messages the controller's message channel
 */
public record ControllerBinding(CurrentRobotState state, MessagePasser messages) {
    private static final ThreadLocal<ControllerBinding> CURRENT = new ThreadLocal<>();

    /**
     * @return the binding of the controller being constructed on this thread
     * @throws IllegalStateException when no backend is constructing a controller
     */
    public static ControllerBinding current() {
        ControllerBinding b = CURRENT.get();
        if (b == null) {
            throw new IllegalStateException("A Controller with no constructor can only be created by"
                    + " the simulator or robot-link; to create one yourself, give it a constructor"
                    + " (CurrentRobotState, MessagePasser) and call super(state, messages)");
        }
        return b;
    }

    static void bind(ControllerBinding binding) {
        if (binding == null) {
            CURRENT.remove();
        } else {
            CURRENT.set(binding);
        }
    }
}
