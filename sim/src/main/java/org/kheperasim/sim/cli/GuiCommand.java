package org.kheperasim.sim.cli;

import java.nio.file.Files;
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
import org.kheperasim.sim.run.ControllerCatalog;
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

    @Option(names = "--robot-file", paramLabel = "FILE",
            description = "the robot for the arena's robot lines that name none: a robot file or a bundled robot"
                    + " (see robots)")
    String robotFile;

    @Option(names = "--controller", paramLabel = "NAME", defaultValue = "WallFollower",
            completionCandidates = BundledControllers.class,
            description = "a bundled controller (${COMPLETION-CANDIDATES}), a class name on --classpath, or"
                    + " a controller's .java file, which the window compiles (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controller classes")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--seed", paramLabel = "N", converter = CliNumbers.AnyLong.class,
            description = "the runs' seed (default: a new one each run, shown in the console)")
    Long seed;

    @Option(names = "--trusted", description = "the controller is your own: run it unchecked (Controller > Trust this"
            + " controller ticked), as a controller that opens a window of its own needs; never for"
            + " someone else's code")
    boolean trusted;

    @Override
    public Integer call() {
        if (robotFile != null) {
            // A wrong robot file is said now, naming its line, as run says it, not by a window that fails to open.
            RobotFiles.arena(arena, robotFile);
        }
        Path source = Path.of(controller.strip());
        if (controller.strip().endsWith(".java") && Files.isRegularFile(source)) {
            // The window compiles it as it opens, as Controller > Open .java does.
            return open(completed(new GuiOptions(arena, controller, classpath, seed, source)));
        }
        // A wrong name is said now, with what to type, not at the first Start (loaded as trusted code only to find
        // it: the window checks its calls when it runs it, and its Trust menu may still allow them).
        new ControllerCatalog(classpath, true).load(controller);
        return open(completed(new GuiOptions(arena, controller, classpath, seed)));
    }

    /** @return the options with --robot-file and --trusted as given */
    private GuiOptions completed(GuiOptions o) {
        GuiOptions robot = o.withRobotFile(robotFile);
        return trusted ? robot.trusting() : robot;
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
