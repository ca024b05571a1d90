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
 * @param javaSource a controller's {@code .java} the window compiles as it opens (as Controller > Open
 *     .java does) and runs, or null
 * @param trusted the controller is the user's own and runs unchecked (Controller > Trust this controller
 *     ticked), as {@code run --trusted}: needed by one that opens a window of its own
 * @param robotFile the robot for the arena's robot lines that name none ({@code --robot-file}: a robot file or a
 *     bundled robot's name), or null for the Khepera I
 */
public record GuiOptions(String arena, String controller, List<Path> classpath, Long seed, Path javaSource,
        boolean trusted, String robotFile) {
    /** Copies the list. */
    public GuiOptions {
        classpath = List.copyOf(classpath);
    }

    /**
     * @param arena an arena file or a bundled arena's name
     * @param controller a bundled controller or a class on the classpath
     * @param classpath folders and jars with compiled controllers
     * @param seed the seed, or null for a new one
     */
    public GuiOptions(String arena, String controller, List<Path> classpath, Long seed) {
        this(arena, controller, classpath, seed, null, false, null);
    }

    /** @param source a controller's {@code .java} to compile and run, as above */
    public GuiOptions(String arena, String controller, List<Path> classpath, Long seed, Path source) {
        this(arena, controller, classpath, seed, source, false, null);
    }

    /** @return these options with the controller trusted */
    public GuiOptions trusting() {
        return new GuiOptions(arena, controller, classpath, seed, javaSource, true, robotFile);
    }

    /**
     * @param robot a robot file or a bundled robot's name, or null
     * @return these options with it as {@code robotFile}
     */
    public GuiOptions withRobotFile(String robot) {
        return new GuiOptions(arena, controller, classpath, seed, javaSource, trusted, robot);
    }

    /** @return maze with WallFollower, the README's first run */
    public static GuiOptions defaults() {
        return new GuiOptions("maze", "WallFollower", List.of(), null);
    }
}
