package org.kheperasim.api.spi;

import java.util.Objects;
import java.util.function.Function;
import org.kheperasim.api.CurrentRobotState;

/**
 * The {@link RobotPort} behind a {@link CurrentRobotState}, for a {@link ControllerStyle} that
 * drives its controllers over the port itself. {@code CurrentRobotState} keeps its port out of the
 * student API; it hands this class the means to read it when it is first initialised.
 */
public final class RobotPorts {
    private static volatile Function<CurrentRobotState, RobotPort> access;

    private RobotPorts() {
    }

    /**
     * Called once, by {@code CurrentRobotState}'s class initialisation.
     *
     * @param accessor reads a state's port
     * @throws IllegalStateException on any later call
     */
    public static synchronized void install(Function<CurrentRobotState, RobotPort> accessor) {
        if (access != null) {
            throw new IllegalStateException("RobotPorts is installed by CurrentRobotState only");
        }
        access = Objects.requireNonNull(accessor, "accessor");
    }

    /**
     * @param state a robot's state, as a backend built it
     * @return the port the state delegates to
     */
    public static RobotPort of(CurrentRobotState state) {
        Objects.requireNonNull(state, "state");
        // An instance exists, so CurrentRobotState has been initialised and has installed the accessor.
        return access.apply(state);
    }
}
