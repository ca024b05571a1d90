package org.kheperasim.sim.testkit;

import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Task;

/**
 * An arena as the testing module sees it: its name, size, regions and the shapes a test asks about.
 * Made by {@link TestKit}; the simulator's own arena stays inside.
 */
public final class KitArena {
    /** A wall: the centre line from (x1, y1) to (x2, y2) and its thickness, mm. */
    public record Wall(double x1, double y1, double x2, double y2, double thickness) {
    }

    /** A lamp's body: its centre and radius, mm. */
    public record Lamp(double x, double y, double radius) {
    }

    final Arena arena;

    KitArena(Arena arena) {
        this.arena = arena;
    }

    /** @return the arena's name */
    public String name() {
        return arena.name();
    }

    /** @return how many robot starts it has */
    public int robotCount() {
        return arena.robots().size();
    }

    /** @return width, mm */
    public double width() {
        return arena.width();
    }

    /** @return height, mm */
    public double height() {
        return arena.height();
    }

    /** @return its named regions, in file order */
    public List<KitRegion> regions() {
        return arena.regions().stream().map(r -> new KitRegion(r.name(), r.x1(), r.y1(), r.x2(), r.y2())).toList();
    }

    /** @return its walls, in file order */
    public List<Wall> walls() {
        return arena.walls().stream().map(w -> new Wall(w.x1(), w.y1(), w.x2(), w.y2(), w.thickness())).toList();
    }

    /** @return its lamps, in file order */
    public List<Lamp> lamps() {
        return arena.lights().stream().map(l -> new Lamp(l.x(), l.y(), l.radius())).toList();
    }

    /** @return how many caps it has */
    public int capCount() {
        return arena.caps().size();
    }

    /** @param cap a cap's index @return its radius, mm */
    public double capRadius(int cap) {
        return arena.caps().get(cap).radius();
    }

    /** @param robot a robot's index (past the last: the first's type) @return its body's radius, mm */
    public double robotRadius(int robot) {
        return arena.robotType(robot < arena.robots().size() ? robot : 0).body().radiusMm();
    }

    /** @param fallback what to give when it sets none @return its {@code time-limit}, s */
    public double timeLimitOr(double fallback) {
        return arena.assignment().secondsOr(fallback);
    }

    /** @param task a task's index @return true when the arena's task at that index is a {@code cover} task */
    public boolean isCoverTask(int task) {
        return arena.assignment().tasks().get(task) instanceof Task.Cover;
    }

    /** @return the SHA-256 of its text, as a trace's header names it */
    public String sha256() {
        return org.kheperasim.sim.arena.ArenaFormat.sha256(arena);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof KitArena k && k.arena.equals(arena);
    }

    @Override
    public int hashCode() {
        return arena.hashCode();
    }

    @Override
    public String toString() {
        return arena.name();
    }
}
