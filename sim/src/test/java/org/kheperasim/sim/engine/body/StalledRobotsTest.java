package org.kheperasim.sim.engine.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * Robots pressing into each other do not move, only turn, until a move no longer heads into the other:
 * the event stepping solves for that tick instead of stepping to it. Compared here with the tick-by-tick
 * reference every 37 ms (stretches of that many ticks for the solving), through a stall of seconds and the
 * parting after it.
 */
class StalledRobotsTest {
    private static final long MS = 1_000_000L;

    private record Pair(Engine engine, List<SimRobot> robots) {
    }

    private static Pair pair(String stepping, int leftA, int rightA, int leftB, int rightB) {
        // With the default noise: wheel speeds whose travel per tick is no round number of pulses.
        Settings settings = Settings.defaults().with("engine.stepping", stepping);
        String text = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 400 600 0\n";
        Engine e = new Engine(new World(ArenaFormat.parse(text, "t.arena")), 1);
        SimRobot a = e.addRobot("a", new Pose(400, 600, 0), settings);
        SimRobot b = e.addRobot("b", new Pose(520, 603, 180), settings);
        a.controls().commandSpeeds(0, leftA, rightA);
        b.controls().commandSpeeds(0, leftB, rightB);
        return new Pair(e, List.of(a, b));
    }

    @ParameterizedTest(name = "a at ({0}, {1}), b at ({2}, {3})")
    @CsvSource({
        "4, 5, 5, 5",   // a turns slowly left while b pushes straight
        "5, 4, 5, 5",   // a turns right
        "5, 5, 5, 5",   // head-on, neither turns: they stay stalled
        "3, 5, 5, 4",   // both turn
        "-2, 6, 6, 6",  // a's centre hardly advances, it turns fast
        "0, 0, 5, 6",   // a stands still, b turns against it
    })
    void aStallLastsAndEndsAtTheTickTheReferenceFinds(int leftA, int rightA, int leftB, int rightB) {
        Pair ev = pair("events", leftA, rightA, leftB, rightB);
        Pair ref = pair("tick", leftA, rightA, leftB, rightB);
        List<SimRobot> events = ev.robots();
        List<SimRobot> tick = ref.robots();
        long stalledMs = 0; // looks at a standing still, turning
        double lastX = Double.NaN;
        double lastHeading = Double.NaN;
        for (long ms = 37; ms <= 12_000; ms += 37) {
            ev.engine().runUntil(ms * MS);
            ref.engine().runUntil(ms * MS);
            for (int i = 0; i < 2; i++) {
                SimRobot p = tick.get(i);
                SimRobot q = events.get(i);
                String at = " of robot " + p.name() + " at " + ms + " ms";
                assertEquals(p.encoderLeft(), q.encoderLeft(), "left encoder" + at);
                assertEquals(p.encoderRight(), q.encoderRight(), "right encoder" + at);
                assertEquals(p.collisions(), q.collisions(), "collisions" + at);
                assertEquals(p.blocked(), q.blocked(), "blocked" + at);
                assertEquals(p.contact(), q.contact(), "contact" + at);
                assertEquals(p.x(), q.x(), 1e-6, "x" + at);
                assertEquals(p.y(), q.y(), 1e-6, "y" + at);
                assertEquals(0, StrictMath.sin(StrictMath.toRadians(p.headingDeg() - q.headingDeg())), 1e-9,
                        "heading" + at);
            }
            SimRobot a = tick.get(0);
            if (a.x() == lastX && a.blocked() && a.headingDeg() != lastHeading) {
                stalledMs++;
            }
            lastX = a.x();
            lastHeading = a.headingDeg();
        }
        if (leftA != rightA) {
            assertTrue(stalledMs > 10, "a stood turning against b for a while: " + stalledMs + " looks");
        }
    }
}
