package org.kheperasim.sim.engine.event;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * The engine's events come at the exact tick a per-tick look at the run shows them, whether the engine
 * stops at every tick or glides for a second at a time, and watching changes nothing of the run.
 */
class EngineEventsTest {
    /** A robot at the bottom facing up (+y) drives through a region into the wall across the box. */
    private static final String BOX = """
            khepera-arena 1
            name box
            size 600 600
            robot 300 100 90
            wall 0 500 600 500 8
            region goal 200 300 400 400
            """;

    /** Per tick: time, x, y and contact of robot 0. */
    private record Tick(long nanos, double x, double y, Contact contact) {
    }

    private static final class Runs {
        final List<Tick> ticks = new ArrayList<>();
        final List<EngineEvent> events = new ArrayList<>();
    }

    /**
     * @param watch true to watch the events
     * @param periodMillis how often a snapshot is taken (the engine stops at least that often)
     */
    private static Runs drive(String arena, boolean watch, long periodMillis, Pose... others) {
        Engine e = new Engine(new World(ArenaFormat.parse(arena, "box.arena")), 7);
        SimRobot r = e.addRobot("r", e.world().arena().robots().get(0), Settings.defaults());
        for (int i = 0; i < others.length; i++) {
            e.addRobot("o" + i, others[i], Settings.defaults());
        }
        r.onBoard().driveSpeeds(10, 10);
        Runs out = new Runs();
        e.addListener(s -> {
            RobotView v = s.robots().get(0);
            out.ticks.add(new Tick(s.timeNanos(), v.x(), v.y(), v.contact()));
        }, periodMillis * Engine.TICK_NANOS);
        if (watch) {
            EngineEvents.watch(e, out.events::add);
        }
        e.runUntil(8_000 * Engine.TICK_NANOS);
        return out;
    }

    private static long firstTick(Runs run, java.util.function.Predicate<Tick> shows) {
        return run.ticks.stream().filter(shows).findFirst().orElseThrow().nanos();
    }

    @Test
    void aRobotDrivenIntoAWallBeginsTouchingItAtTheFirstTickThatShowsTheContact() {
        Runs run = drive(BOX, true, 1);
        long shown = firstTick(run, t -> t.contact() != Contact.NONE);
        ContactBegan began = run.events.stream().filter(ContactBegan.class::isInstance).map(ContactBegan.class::cast)
                .findFirst().orElseThrow();
        assertEquals(shown, began.timeNanos(), "the contact's tick");
        assertEquals(new Touched(Touched.Kind.WALL, 0), began.touched());
        assertEquals(Contact.FRONT, began.side());
        assertTrue(shown > 4_000 * Engine.TICK_NANOS, "it drove ~370 mm at ~80 mm/s first: " + shown);
    }

    @Test
    void aRegionIsEnteredAtTheFirstTickThePoseIsInsideItAndLeftAtTheFirstOutside() {
        Runs run = drive(BOX, true, 1);
        Region goal = new Region("goal", 200, 300, 400, 400);
        long in = firstTick(run, t -> goal.contains(t.x(), t.y()));
        long out = firstTick(run, t -> t.nanos() > in && !goal.contains(t.x(), t.y()));
        List<EngineEvent> regionEvents = run.events.stream()
                .filter(ev -> ev instanceof RegionEntered || ev instanceof RegionLeft).toList();
        assertEquals(2, regionEvents.size(), regionEvents.toString());
        RegionEntered entered = assertInstanceOf(RegionEntered.class, regionEvents.get(0));
        assertEquals(in, entered.timeNanos());
        assertEquals(goal, entered.region());
        assertEquals(out, assertInstanceOf(RegionLeft.class, regionEvents.get(1)).timeNanos());
    }

    @Test
    void aRunThatGlidesASecondAtATimeHasItsContactAndFirstEntryAtTheSameTicks() {
        Runs everyTick = drive(BOX, true, 1);
        Runs everySecond = drive(BOX, true, 1000);
        assertEquals(times(everyTick, ContactBegan.class), times(everySecond, ContactBegan.class));
        assertEquals(times(everyTick, RegionEntered.class), times(everySecond, RegionEntered.class));
        assertFalse(times(everySecond, ContactBegan.class).isEmpty());
    }

    @Test
    void watchingChangesNothingOfTheRun() {
        assertEquals(drive(BOX, false, 1).ticks, drive(BOX, true, 1).ticks);
        assertEquals(drive(BOX, false, 1000).ticks, drive(BOX, true, 1000).ticks);
    }

    @Test
    void aRobotDrivenIntoAnotherTouchesThatRobot() {
        Runs run = drive(BOX, true, 50, new Pose(300, 250, 0));
        ContactBegan began = run.events.stream().filter(ContactBegan.class::isInstance).map(ContactBegan.class::cast)
                .findFirst().orElseThrow();
        assertEquals(new Touched(Touched.Kind.ROBOT, 1), began.touched());
        assertEquals(0, began.robot());
    }

    @Test
    void eventsComeInTimeOrderAndTheSameOnEveryRun() {
        Runs a = drive(BOX, true, 20, new Pose(100, 350, 0));
        Runs b = drive(BOX, true, 20, new Pose(100, 350, 0));
        assertEquals(a.events, b.events);
        for (int k = 1; k < a.events.size(); k++) {
            assertTrue(a.events.get(k - 1).timeNanos() <= a.events.get(k).timeNanos(), a.events.toString());
        }
    }

    /** 64 robots, one per 200 mm cell of a walled square, each driving its own arc: a swarm the engine may split. */
    private static List<EngineEvent> swarm(int threads) {
        StringBuilder a = new StringBuilder("khepera-arena 1\nname swarm\nsize 1600 1600\n");
        a.append("wall 0 4 1600 4 8\nwall 0 1596 1600 1596 8\nwall 4 0 4 1600 8\nwall 1596 0 1596 1600 8\n");
        a.append("region middle 600 600 1000 1000\n");
        for (int i = 0; i < 64; i++) {
            a.append("robot ").append(100 + 200 * (i % 8)).append(' ').append(100 + 200 * (i / 8)).append(' ')
                    .append(45 * (i % 8)).append('\n');
        }
        Engine e = new Engine(new World(ArenaFormat.parse(a.toString(), "swarm.arena")), 3);
        for (Pose p : e.world().arena().robots()) {
            SimRobot r = e.addRobot("r", p, Settings.defaults());
            r.onBoard().driveSpeeds(12, 8 + r.id() % 5);
        }
        e.threads(threads);
        List<EngineEvent> events = new ArrayList<>();
        EngineEvents.watch(e, events::add);
        try {
            e.runUntil(10_000 * Engine.TICK_NANOS);
        } finally {
            e.close();
        }
        return events;
    }

    @Test
    void aSwarmMovedOnTwoThreadsHasTheSameEventsInTheSameOrder() {
        List<EngineEvent> one = swarm(1);
        assertTrue(one.stream().anyMatch(ContactBegan.class::isInstance), one.size() + " events");
        assertTrue(one.stream().anyMatch(RegionLeft.class::isInstance), one.size() + " events");
        assertEquals(one, swarm(2));
    }

    private static List<Long> times(Runs run, Class<? extends EngineEvent> kind) {
        return run.events.stream().filter(kind::isInstance).map(EngineEvent::timeNanos).toList();
    }
}
