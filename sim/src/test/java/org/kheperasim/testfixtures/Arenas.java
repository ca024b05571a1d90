package org.kheperasim.testfixtures;

import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;

/** Arenas more than one test uses. */
public final class Arenas {
    /** A walled lab-sized square with three robots well apart. */
    public static final Arena THREE = ArenaFormat.parse("""
            khepera-arena 1
            name three
            size 1219.2 1219.2
            wall 0 4 1219.2 4 8
            wall 0 1215.2 1219.2 1215.2 8
            wall 4 0 4 1219.2 8
            wall 1215.2 0 1215.2 1219.2 8
            robot 300 300 0
            robot 900 300 90
            robot 600 900 180
            """, "three.arena");

    private Arenas() {
    }
}
