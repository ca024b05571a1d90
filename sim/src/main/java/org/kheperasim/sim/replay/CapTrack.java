package org.kheperasim.sim.replay;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.kheperasim.sim.engine.view.CapView;

/** Where each cap was over a run: its moves, as a trace's cap lines give them, and the cap at any time. */
final class CapTrack {
    private final List<double[]> times = new ArrayList<>();
    private final List<double[]> xs = new ArrayList<>();
    private final List<double[]> ys = new ArrayList<>();
    private final List<int[]> held = new ArrayList<>();
    private int[] sizes;
    private double[] radii;

    /** @param radii each cap's radius, mm, in arena order */
    CapTrack(double[] radii) {
        this.radii = radii.clone();
        sizes = new int[radii.length];
        for (int i = 0; i < radii.length; i++) {
            times.add(new double[8]);
            xs.add(new double[8]);
            ys.add(new double[8]);
            held.add(new int[8]);
        }
    }

    /** @return caps tracked */
    int count() {
        return radii.length;
    }

    /**
     * @param cap its id (a cap the arena lacks is added with the default radius)
     * @param t s
     * @param x mm
     * @param y mm
     * @param heldBy robot id or -1
     */
    void add(int cap, double t, double x, double y, int heldBy) {
        while (cap >= radii.length) {
            radii = Arrays.copyOf(radii, radii.length + 1);
            radii[radii.length - 1] = org.kheperasim.sim.arena.Cap.DEFAULT_RADIUS;
            sizes = Arrays.copyOf(sizes, radii.length);
            times.add(new double[8]);
            xs.add(new double[8]);
            ys.add(new double[8]);
            held.add(new int[8]);
        }
        int n = sizes[cap];
        if (n == times.get(cap).length) {
            times.set(cap, Arrays.copyOf(times.get(cap), n * 2));
            xs.set(cap, Arrays.copyOf(xs.get(cap), n * 2));
            ys.set(cap, Arrays.copyOf(ys.get(cap), n * 2));
            held.set(cap, Arrays.copyOf(held.get(cap), n * 2));
        }
        times.get(cap)[n] = t;
        xs.get(cap)[n] = x;
        ys.get(cap)[n] = y;
        held.get(cap)[n] = heldBy;
        sizes[cap] = n + 1;
    }

    /** @param t s @return every cap as it was at {@code t} (where it was first seen before its first line) */
    List<CapView> at(double t) {
        List<CapView> out = new ArrayList<>(radii.length);
        for (int c = 0; c < radii.length; c++) {
            int n = sizes[c];
            if (n == 0) {
                continue;
            }
            int i = Arrays.binarySearch(times.get(c), 0, n, t);
            if (i < 0) {
                i = StrictMath.max(0, -i - 2);
            } else {
                while (i + 1 < n && times.get(c)[i + 1] == t) {
                    i++;
                }
            }
            out.add(new CapView(c, xs.get(c)[i], ys.get(c)[i], radii[c], held.get(c)[i]));
        }
        return out;
    }
}
