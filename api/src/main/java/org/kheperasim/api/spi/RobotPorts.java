package org.kheperasim.api.spi;

import java.util.Objects;
import java.util.function.Function;

/**
 * The {@link RobotPort} behind a robot's state ({@code CurrentRobotState}), for a backend's
 * controller style that drives its controllers over the port itself. The state keeps its port out
 * of the student API; it hands this class the means to read it when it is first initialised. The
 * port layer lies below the student API, so the state's type is given at installation, not named.
 */
public final class RobotPorts {
    private static volatile Accessor<?> access;

    private record Accessor<S>(Class<S> type, Function<S, RobotPort> read) {
        RobotPort of(Object state) {
            return read.apply(type.cast(state));
        }
    }

    private RobotPorts() {
    }

    /**
     * Called once, by {@code CurrentRobotState}'s class initialisation.
     *
     * @param <S> the state's type
     * @param stateType the state's class
     * @param accessor reads a state's port
     * @throws IllegalStateException on any later call
     */
    public static synchronized <S> void install(Class<S> stateType, Function<S, RobotPort> accessor) {
        if (access != null) {
            throw new IllegalStateException("RobotPorts is installed by CurrentRobotState only");
        }
        access = new Accessor<>(Objects.requireNonNull(stateType, "stateType"),
                Objects.requireNonNull(accessor, "accessor"));
    }

    /**
     * @param state a robot's state ({@code CurrentRobotState}), as a backend built it
     * @return the port the state delegates to
     * @throws ClassCastException when {@code state} is not the installed state type
     */
    public static RobotPort of(Object state) {
        Objects.requireNonNull(state, "state");
        // An instance exists, so CurrentRobotState has been initialised and has installed the accessor.
        return access.of(state);
    }
}
