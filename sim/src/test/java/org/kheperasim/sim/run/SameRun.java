package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * What "the same run" means when the event-driven engine is checked against the reference that
 * steps every millisecond: at every snapshot the readings the controllers see, the wheel speeds,
 * encoders, contacts, collisions, grippers and cap holders are equal, and poses agree within 1 µm
 * (the two compose the same arcs in different pieces, so they differ only by rounding).
 */
final class SameRun {
    static final double POSE_MM = 1e-3;

    private SameRun() {
    }

    static void assertSameSnapshots(List<Snapshot> tick, List<Snapshot> events) {
        assertEquals(tick.size(), events.size(), "snapshots");
        for (int k = 0; k < tick.size(); k++) {
            Snapshot a = tick.get(k);
            Snapshot b = events.get(k);
            String at = " at " + a.timeSeconds() + " s";
            assertEquals(a.timeNanos(), b.timeNanos(), "time" + at);
            for (int i = 0; i < a.robots().size(); i++) {
                RobotView p = a.robots().get(i);
                RobotView q = b.robots().get(i);
                String who = " of robot " + i + at;
                assertArrayEquals(p.proximity(), q.proximity(), "proximity readings" + who);
                assertArrayEquals(p.light(), q.light(), "light readings" + who);
                assertEquals(p.speedLeft(), q.speedLeft(), "left speed" + who);
                assertEquals(p.speedRight(), q.speedRight(), "right speed" + who);
                assertEquals(p.encoderLeft(), q.encoderLeft(), "left encoder" + who);
                assertEquals(p.encoderRight(), q.encoderRight(), "right encoder" + who);
                assertEquals(p.contact(), q.contact(), "contact" + who);
                assertEquals(p.collisions(), q.collisions(), "collisions" + who);
                assertEquals(p.gripper(), q.gripper(), "gripper" + who);
                assertEquals(p.x(), q.x(), POSE_MM, "x" + who);
                assertEquals(p.y(), q.y(), POSE_MM, "y" + who);
                assertEquals(0, StrictMath.sin(StrictMath.toRadians(p.headingDeg() - q.headingDeg())), 1e-6, "heading" + who);
            }
            for (int c = 0; c < a.caps().size(); c++) {
                CapView p = a.caps().get(c);
                CapView q = b.caps().get(c);
                assertEquals(p.heldBy(), q.heldBy(), "cap " + c + " holder" + at);
                assertEquals(p.x(), q.x(), POSE_MM, "cap " + c + " x" + at);
                assertEquals(p.y(), q.y(), POSE_MM, "cap " + c + " y" + at);
            }
        }
    }
}
