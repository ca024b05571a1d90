package org.kheperasim.api.spi;

/**
 * Hands the robot's state to a {@link org.kheperasim.api.Controller} subclass that declares no
 * constructor: the backend binds the state to the creating thread while the constructor runs.
 *
 * <p>The port layer knows nothing of the student API's types (it lies below them), so the two are
 * held as objects: the backend binds a {@code CurrentRobotState} and a {@code MessagePasser}, and
 * the controller's constructor, which knows their types, reads them back.
 *
 * @param state the robot's live state (a {@code CurrentRobotState})
 * @param messages the controller's message channel (a {@code MessagePasser})
 */
public record ControllerBinding(Object state, Object messages) {
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

    /**
     * Called by the backend around the constructor of a controller that declares none.
     *
     * @param binding the state and messages to hand it, or null to clear this thread's binding
     */
    public static void bind(ControllerBinding binding) {
        if (binding == null) {
            CURRENT.remove();
        } else {
            CURRENT.set(binding);
        }
    }
}
