package org.kheperasim.sim.arena;

import java.util.List;

/**
 * One part of an arena's assignment ({@code task} lines of an arena file): what a run earns points
 * for. The model only names what to do; {@code org.kheperasim.sim.task.Score} computes how much of
 * it a run did. Points are earned in proportion to the fraction done.
 */
public sealed interface Task permits Task.Visit, Task.Cover, Task.Deliver, Task.Reach {

    /** Points of a task line without {@code points}. */
    double DEFAULT_POINTS = 100;
    /** Most points one task may carry. */
    double MAX_POINTS = 1_000_000;

    /** @return the points the task is worth when fully done, ≥ 0 */
    double points();

    /** @return the task as a line of an arena file, without a trailing newline */
    String line();

    /**
     * Visit regions: the fraction of the matched regions that some robot's centre entered.
     *
     * @param patterns region names, or prefixes ending in {@code *} ({@code c*} = every region whose
     *     name starts with {@code c}; {@code *} = every region)
     * @param points   points when every matched region was entered
     */
    record Visit(List<String> patterns, double points) implements Task {
        /** Copies the list; needs at least one pattern. */
        public Visit {
            patterns = List.copyOf(patterns);
            if (patterns.isEmpty()) {
                throw new IllegalArgumentException("task visit needs at least one region name or prefix*");
            }
            points = checkPoints(points);
        }

        /** @param arena the arena @return the regions the patterns match, in arena order */
        public List<Region> regions(Arena arena) {
            return arena.regions().stream().filter(r -> patterns.stream().anyMatch(p -> matches(p, r.name()))).toList();
        }

        /** @return true when {@code pattern} (a name, or a prefix ending in *) matches {@code name} */
        static boolean matches(String pattern, String name) {
            return pattern.endsWith("*") ? name.startsWith(pattern.substring(0, pattern.length() - 1))
                    : pattern.equals(name);
        }

        @Override
        public String line() {
            return "task visit " + String.join(" ", patterns) + pointsSuffix(points);
        }
    }

    /**
     * Cover the floor: the fraction of {@code percent} of the floor's cells that the best robot's
     * body covered (as the run's {@code visitedPercent}).
     *
     * @param percent the share of the floor to cover for full points, 0 &lt; percent ≤ 100
     * @param points  points for covering it
     */
    record Cover(double percent, double points) implements Task {
        /** Checks the range. */
        public Cover {
            if (!(percent > 0 && percent <= 100)) {
                throw new IllegalArgumentException("task cover percent is " + Numbers.brief(percent)
                        + "; give the share of the floor to cover, more than 0 and at most 100");
            }
            points = checkPoints(points);
        }

        @Override
        public String line() {
            return "task cover " + Numbers.format(percent) + pointsSuffix(points);
        }
    }

    /**
     * Deliver caps into a region: the caps lying on the floor inside it at the end, out of
     * {@code count} (0 = every cap of the arena).
     *
     * @param count  caps to deliver for full points; 0 for all of them
     * @param region the region's name
     * @param points points for delivering them
     */
    record Deliver(int count, String region, double points) implements Task {
        /** Checks the count. */
        public Deliver {
            if (count < 0) {
                throw new IllegalArgumentException("task deliver count is " + count
                        + "; give a whole number ≥ 1, or leave it out for every cap");
            }
            points = checkPoints(points);
        }

        @Override
        public String line() {
            return "task deliver " + (count > 0 ? count + " " : "") + "caps into " + region + pointsSuffix(points);
        }
    }

    /**
     * Reach a goal region: full points when some robot's centre entered it within the run.
     *
     * @param region the goal region's name
     * @param points points for reaching it
     */
    record Reach(String region, double points) implements Task {
        /** Checks the points. */
        public Reach {
            points = checkPoints(points);
        }

        @Override
        public String line() {
            return "task reach " + region + pointsSuffix(points);
        }
    }

    private static double checkPoints(double points) {
        if (!(points >= 0 && points <= MAX_POINTS)) {
            throw new IllegalArgumentException("task points are " + Numbers.brief(points) + "; give 0 to "
                    + Numbers.brief(MAX_POINTS));
        }
        return points;
    }

    private static String pointsSuffix(double points) {
        return Double.compare(points, DEFAULT_POINTS) == 0 ? "" : " points " + Numbers.format(points);
    }
}
