package org.kheperasim.sim.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.kheperasim.sim.gui.GuiLauncher;
import org.kheperasim.sim.gui.GuiOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code gui}: open the window (also what {@code khepera-sim} with no command does). */
@Command(name = "gui", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Open the simulator's window: arena editing, run controls, sensor panel, console.",
            "Needs a display; without one, use 'run' (headless) or set DISPLAY."})
final class GuiCommand implements Callable<Integer> {

    @Option(names = "--arena", paramLabel = "FILE", defaultValue = "maze",
            description = "an arena file, or a bundled arena (lab, maze, two-rooms; see list) (default: ${DEFAULT-VALUE})")
    String arena;

    @Option(names = "--controller", paramLabel = "NAME", defaultValue = "WallFollower",
            description = "a bundled controller or a class name on --classpath (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controller classes")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--seed", paramLabel = "N", description = "the runs' seed (default: a new one each run, shown in the console)")
    Long seed;

    @Override
    public Integer call() {
        return open(new GuiOptions(arena, controller, classpath, seed));
    }

    static int open(GuiOptions options) {
        try {
            GuiLauncher.launch(options);
            return 0;
        } catch (GuiLauncher.NoDisplayException e) {
            System.err.println("khepera-sim: " + e.getMessage());
            return 3;
        }
    }
}
