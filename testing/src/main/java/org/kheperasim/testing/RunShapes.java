package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kheperasim.sim.testkit.KitArena;
import org.kheperasim.sim.testkit.KitContact;
import org.kheperasim.sim.testkit.KitRegion;
import org.kheperasim.sim.testkit.KitScore;

/** The parts of a {@link Run} made from a trace's samples, the same for a live run and a recorded one. */
final class RunShapes {
    private RunShapes() {
    }

    /** @return a robot's samples as its path */
    static List<PathPoint> path(TraceSamples.Series s) {
        List<PathPoint> out = new ArrayList<>(s.size);
        for (int k = 0; k < s.size; k++) {
            out.add(new PathPoint(new SimTime(s.nanos[k]), s.x[k], s.y[k], s.heading[k]));
        }
        return out;
    }

    /** @return every cap: where it started and ended, when it first moved, where it lies at the end */
    static List<Cap> caps(TraceSamples samples, KitArena arena) {
        List<Cap> out = new ArrayList<>();
        for (int i = 0; i < samples.caps.size(); i++) {
            List<TraceSamples.CapState> moves = samples.caps.get(i);
            TraceSamples.CapState first = moves.get(0);
            TraceSamples.CapState last = moves.get(moves.size() - 1);
            Optional<SimTime> firstMoved = Optional.empty();
            for (TraceSamples.CapState c : moves) {
                if (c.x() != first.x() || c.y() != first.y() || c.heldBy() >= 0) {
                    firstMoved = Optional.of(new SimTime(c.nanos()));
                    break;
                }
            }
            Optional<String> region = Optional.empty();
            if (last.heldBy() < 0) {
                region = arena.regions().stream().filter(r -> r.contains(last.x(), last.y())).map(KitRegion::name)
                        .findFirst();
            }
            out.add(new Cap(i, first.x(), first.y(), last.x(), last.y(), firstMoved, last.heldBy(), region));
        }
        return out;
    }

    /** @return the regions a robot's centre was in at some sample, with the first such sample's time, in arena order */
    static Map<String, SimTime> regionsEntered(TraceSamples.Series s, KitArena arena) {
        Map<String, SimTime> out = new LinkedHashMap<>();
        for (KitRegion r : arena.regions()) {
            for (int k = 0; k < s.size; k++) {
                if (r.contains(s.x[k], s.y[k])) {
                    out.put(r.name(), new SimTime(s.nanos[k]));
                    break;
                }
            }
        }
        return out;
    }

    /** @return the length of a robot's sampled path, mm */
    static double pathLength(TraceSamples.Series s) {
        double d = 0;
        for (int k = 1; k < s.size; k++) {
            d += StrictMath.hypot(s.x[k] - s.x[k - 1], s.y[k] - s.y[k - 1]);
        }
        return d;
    }

    /** @return the simulator's score in the testing API's terms */
    static Score score(KitScore s) {
        List<TaskScore> tasks = new ArrayList<>();
        for (KitScore.Part p : s.parts()) {
            tasks.add(new TaskScore(p.task(), p.fraction(), p.points(), p.max(), p.detail()));
        }
        return new Score(tasks, s.points(), s.max());
    }

    /** @return what the testing API calls a thing the engine says was touched (the arena's edge is a wall) */
    static Obstacle obstacle(KitContact.Kind kind) {
        return switch (kind) {
            case WALL, ARENA_EDGE -> Obstacle.WALL;
            case LAMP -> Obstacle.LAMP;
            case ROBOT -> Obstacle.ROBOT;
            case CAP -> Obstacle.CAP;
        };
    }

    /**
     * @param x a point, mm
     * @param y a point, mm
     * @param r a region
     * @return the distance from the point to the region's rectangle, mm (0 inside it)
     */
    static double distanceTo(double x, double y, KitRegion r) {
        double dx = StrictMath.max(0, StrictMath.max(r.x1() - x, x - r.x2()));
        double dy = StrictMath.max(0, StrictMath.max(r.y1() - y, y - r.y2()));
        return StrictMath.hypot(dx, dy);
    }
}
