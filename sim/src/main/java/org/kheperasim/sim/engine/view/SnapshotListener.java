package org.kheperasim.sim.engine.view;

/** Receives the engine's snapshots. Called on the engine's thread: keep it short, never block. */
@FunctionalInterface
public interface SnapshotListener {
    /** @param snapshot the world at this instant */
    void onSnapshot(Snapshot snapshot);
}
