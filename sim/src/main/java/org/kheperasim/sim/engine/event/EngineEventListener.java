package org.kheperasim.sim.engine.event;

/**
 * Hears a run's {@link EngineEvent}s, on the thread that holds the engine's turn, between ticks, in
 * their order. It must be quick, and must not call into the engine or a controller.
 */
@FunctionalInterface
public interface EngineEventListener {
    /** @param event what happened */
    void onEvent(EngineEvent event);
}
