package org.kheperasim.sim.testkit;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.event.ContactBegan;
import org.kheperasim.sim.engine.event.ContactEnded;
import org.kheperasim.sim.engine.event.EngineEvent;
import org.kheperasim.sim.engine.event.EngineEventListener;

/** Pairs a run's contact events into each robot's {@link KitContact}s. */
final class ContactLog implements EngineEventListener {
    private final List<List<KitContact>> done = new ArrayList<>();
    private final List<ContactBegan> open = new ArrayList<>();

    ContactLog(int robots) {
        for (int i = 0; i < robots; i++) {
            done.add(new ArrayList<>());
            open.add(null);
        }
    }

    @Override
    public synchronized void onEvent(EngineEvent event) {
        if (event instanceof ContactBegan b && b.robot() < open.size()) {
            open.set(b.robot(), b);
        } else if (event instanceof ContactEnded e && e.robot() < open.size() && open.get(e.robot()) != null) {
            close(e.robot(), e.timeNanos() - Engine.TICK_NANOS);
        }
    }

    private void close(int robot, long lastNanos) {
        ContactBegan b = open.get(robot);
        KitContact.Kind kind = KitContact.Kind.valueOf(b.touched().kind().name());
        done.get(robot).add(new KitContact(b.timeNanos(), StrictMath.max(b.timeNanos(), lastNanos), kind,
                b.touched().index(), b.side().name(), b.x(), b.y()));
        open.set(robot, null);
    }

    /**
     * @param robot a robot's index
     * @param endNanos the run's end: a contact still open then lasts to it
     * @return its contacts, in time order
     */
    synchronized List<KitContact> contacts(int robot, long endNanos) {
        if (robot >= done.size()) {
            return List.of();
        }
        if (open.get(robot) != null) {
            close(robot, endNanos);
        }
        return List.copyOf(done.get(robot));
    }
}
