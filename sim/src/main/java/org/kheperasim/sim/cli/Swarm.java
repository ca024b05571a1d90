package org.kheperasim.sim.cli;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;

/** The benchmark's swarm: an arena made for N robots, and the figures a swarm run is judged by besides speed. */
final class Swarm {
    /** Each robot has a square of this side to itself, mm. */
    static final double CELL_MM = 200;
    private static final double WALL_MM = 8;

    private Swarm() {
    }

    /**
     * A walled square for {@code n} robots, one in the middle of each 200 mm cell of a square grid
     * (filled row by row), each facing its own way.
     */
    static Arena arena(int n) {
        int side = (int) StrictMath.ceil(StrictMath.sqrt(n));
        double size = side * CELL_MM + 2 * WALL_MM;
        List<Pose> robots = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double x = WALL_MM + (i % side + 0.5) * CELL_MM;
            double y = WALL_MM + (i / side + 0.5) * CELL_MM;
            robots.add(new Pose(x, y, (i * 137) % 360 - 180));
        }
        double h = WALL_MM / 2;
        List<Wall> walls = List.of(new Wall(0, h, size, h, WALL_MM), new Wall(0, size - h, size, size - h, WALL_MM),
                new Wall(h, 0, h, size, WALL_MM), new Wall(size - h, 0, size - h, size, WALL_MM));
        return new Arena("swarm-" + n, size, size, robots, walls, List.of(), List.of(), List.of());
    }

    /**
     * Time a run's set-up (a run of one tick) and print it with the heap's peak use so far and the
     * heap a run holds: measured once more in a second such run, after a full collection while its
     * world and robots are alive ({@code measuredRun} runs the measurement it is given from inside
     * the run, at its first snapshot).
     */
    static void printSetUpAndMemory(Runnable oneTick, java.util.function.Consumer<Runnable> measuredRun) {
        long t0 = System.nanoTime();
        oneTick.run();
        double setUp = (System.nanoTime() - t0) / 1e9;
        long peak = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP && pool.getPeakUsage() != null) {
                peak += pool.getPeakUsage().getUsed();
            }
        }
        long[] live = new long[1];
        measuredRun.accept(() -> {
            if (live[0] == 0) {
                System.gc();
                live[0] = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
            }
        });
        System.out.printf(Locale.ROOT,
                "set-up of a run (construction, 1 ms simulated, teardown): %.3f s; peak heap in use"
                + " (sum of the pools' peaks, garbage included: an upper bound): %,d MB; live while a run"
                + " is set up, after a full collection: %,d MB; heap limit %,d MB (-Xmx)%n", setUp, peak >> 20,
                live[0] >> 20, Runtime.getRuntime().maxMemory() >> 20);
    }
}
