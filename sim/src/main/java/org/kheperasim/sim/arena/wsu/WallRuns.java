package org.kheperasim.sim.arena.wsu;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Joins wall bars that continue one another into runs. In the original a wall is a solid 8 x 50 px
 * rectangle of its grid, and bars laid end to end make one continuous wall; drawn as separate
 * walls with rounded ends, each joint would get a notch a sensor sees. Bars with the same cross
 * extent (the same rows for horizontal bars, the same columns for vertical ones) that touch or
 * overlap along their length become one bar.
 */
final class WallRuns {
    /**
     * A solid rectangle of the panel, px edges {@code [x0, x1) x [y0, y1)}, y down.
     *
     * @param order where its first bar came in the file, to keep the file's order
     */
    record Bar(double x0, double y0, double x1, double y1, int order) {
        boolean horizontal() {
            return x1 - x0 >= y1 - y0;
        }
    }

    private WallRuns() {
    }

    /**
     * @param bars bars in file order
     * @return the runs, in the order of each run's first bar
     */
    static List<Bar> join(List<Bar> bars) {
        List<Bar> horizontal = new ArrayList<>();
        List<Bar> vertical = new ArrayList<>();
        for (Bar b : bars) {
            (b.horizontal() ? horizontal : vertical).add(b);
        }
        List<Bar> runs = new ArrayList<>();
        runs.addAll(joinAlong(horizontal, true));
        runs.addAll(joinAlong(vertical, false));
        runs.sort(Comparator.comparingInt(Bar::order));
        return runs;
    }

    private static List<Bar> joinAlong(List<Bar> bars, boolean horizontal) {
        List<Bar> sorted = new ArrayList<>(bars);
        sorted.sort(horizontal
                ? Comparator.comparingDouble(Bar::y0).thenComparingDouble(Bar::y1).thenComparingDouble(Bar::x0)
                : Comparator.comparingDouble(Bar::x0).thenComparingDouble(Bar::x1).thenComparingDouble(Bar::y0));
        List<Bar> runs = new ArrayList<>();
        Bar run = null;
        for (Bar b : sorted) {
            if (run != null && continues(run, b, horizontal)) {
                run = horizontal
                        ? new Bar(run.x0(), run.y0(), Math.max(run.x1(), b.x1()), run.y1(),
                                Math.min(run.order(), b.order()))
                        : new Bar(run.x0(), run.y0(), run.x1(), Math.max(run.y1(), b.y1()),
                                Math.min(run.order(), b.order()));
            } else {
                if (run != null) {
                    runs.add(run);
                }
                run = b;
            }
        }
        if (run != null) {
            runs.add(run);
        }
        return runs;
    }

    /**
     * Whether {@code b} (sorted after {@code run}) has the same cross extent and starts where the run has not ended.
     */
    private static boolean continues(Bar run, Bar b, boolean horizontal) {
        return horizontal
                ? run.y0() == b.y0() && run.y1() == b.y1() && b.x0() <= run.x1()
                : run.x0() == b.x0() && run.x1() == b.x1() && b.y0() <= run.y1();
    }
}
