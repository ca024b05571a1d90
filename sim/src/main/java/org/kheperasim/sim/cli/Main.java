package org.kheperasim.sim.cli;

import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.link.tool.ToolVersion;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The simulator's entry point: {@code java -jar khepera-sim.jar <command>}. With no command it
 * opens the window with {@code maze} loaded and {@code WallFollower} chosen.
 */
@Command(name = "khepera-sim", mixinStandardHelpOptions = true, versionProvider = ToolVersion.class,
        description = "A deterministic Khepera robot simulator. Runs a controller class in an arena.",
        subcommands = {GuiCommand.class, GuiBenchCommand.class, RunCommand.class, BenchCommand.class, SettingsCommand.class,
            ListCommand.class, RobotsCommand.class, ServeCommand.class, ImportWsuCommand.class, VerifyCommand.class, GradeCommand.class,
            ReplayCommand.class, EvaluateCommand.class, CalibrationReportCommand.class, CompareCommand.class,
            CommandLine.HelpCommand.class})
public final class Main implements java.util.concurrent.Callable<Integer> {
    static {
        org.kheperasim.link.tool.PicocliStartup.skipUnusedConverters();
    }

    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    /** With no command: open the window with the defaults (maze, WallFollower). */
    @Override
    public Integer call() {
        return GuiCommand.open(org.kheperasim.sim.gui.GuiOptions.defaults());
    }

    /** @return a command line ready to execute, with the project's error handling */
    public static CommandLine commandLine() {
        return HelpFormat.install(ErrorLine.install(ToolErrors.install(new CommandLine(new Main()), ErrorLine.TOOL)));
    }

    /**
     * A command line for these arguments: when they name a subcommand, only that one is built
     * (picocli reads every annotated option by reflection, which costs a tenth of a second for all
     * of them at every start); otherwise every subcommand, for the top-level help.
     *
     * @param args command-line arguments
     * @return a command line ready to execute them
     */
    static CommandLine commandLineFor(String[] args) {
        Class<?> type = args.length > 0 ? subcommand(args[0]) : null;
        if (type == null) {
            return commandLine();
        }
        CommandLine top = new CommandLine(new Lean());
        top.addSubcommand(args[0], type);
        return HelpFormat.install(ErrorLine.install(ToolErrors.install(top, ErrorLine.TOOL)));
    }

    /**
     * The subcommand class of this name, found by the classes' naming ({@code gui-bench} is
     * {@code GuiBenchCommand}) so that only it is loaded: reading {@link Main}'s own annotation
     * would load all of them, a few hundredths of a second at every start.
     *
     * @return the class, or null when no subcommand has this name
     */
    static Class<?> subcommand(String name) {
        if (!name.matches("[a-z]+(-[a-z]+)*")) {
            return null;
        }
        StringBuilder cls = new StringBuilder(Main.class.getPackageName()).append('.');
        for (String part : name.split("-")) {
            cls.append(Character.toUpperCase(part.charAt(0))).append(part, 1, part.length());
        }
        try {
            Class<?> type = Class.forName(cls.append("Command").toString(), false, Main.class.getClassLoader());
            Command c = type.getAnnotation(Command.class);
            return c != null && c.name().equals(name) ? type : null;
        } catch (ClassNotFoundException e) {
            return null;
        }
    }

    /** The top-level command when only one subcommand is built. */
    @Command(name = "khepera-sim", mixinStandardHelpOptions = true, versionProvider = ToolVersion.class)
    static final class Lean implements java.util.concurrent.Callable<Integer> {
        @Override
        public Integer call() {
            return GuiCommand.open(org.kheperasim.sim.gui.GuiOptions.defaults());
        }
    }

    /**
     * Runs the command line. The process exit status is the only way a script learns whether the
     * run succeeded, so a failure exits non-zero here, and only here.
     *
     * @param args command-line arguments
     */
    public static void main(String[] args) {
        int code;
        try {
            code = commandLineFor(args).execute(args);
        } catch (OutOfMemoryError e) {
            code = ErrorLine.outOfMemory(e);
        }
        if (code != 0) {
            System.exit(code);
        }
    }
}
