package org.kheperasim.sim.gui;

import java.nio.file.Path;
import java.util.List;

/**
 * How the window starts.
 *
 * @param arena an arena file or a bundled arena's name
 * @param controller a bundled controller or a class on the classpath
 * @param classpath folders and jars with compiled controllers
 * @param seed the seed, or null for a new one
 */
public record GuiOptions(String arena, String controller, List<Path> classpath, Long seed) {
    /** Copies the list. */
    public GuiOptions {
        classpath = List.copyOf(classpath);
    }

    /** @return maze with WallFollower, the README's first run */
    public static GuiOptions defaults() {
        return new GuiOptions("maze", "WallFollower", List.of(), null);
    }
}
