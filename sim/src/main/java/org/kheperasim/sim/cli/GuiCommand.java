package org.kheperasim.sim.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.BundledControllers;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
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
            completionCandidates = BundledArenas.class,
            description = "an arena file, or a bundled arena (${COMPLETION-CANDIDATES}) (default: ${DEFAULT-VALUE})")
    String arena;

    @Option(names = "--controller", paramLabel = "NAME", defaultValue = "WallFollower",
            completionCandidates = BundledControllers.class,
            description = "a bundled controller (${COMPLETION-CANDIDATES}) or a class name on --classpath (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controller classes")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--seed", paramLabel = "N", converter = CliNumbers.AnyLong.class, description = "the runs' seed (default: a new one each run, shown in the console)")
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
            System.err.println(ToolErrors.prefix("khepera-sim") + e.getMessage());
            return ExitCodes.BAD_INPUT;
        }
    }
}
