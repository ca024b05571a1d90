package org.kheperasim.sim.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The simulator's entry point: {@code java -jar khepera-sim.jar <command>}. With no command it
 * opens the window with {@code maze} loaded and {@code WallFollower} chosen.
 */
@Command(name = "khepera-sim", mixinStandardHelpOptions = true, version = "khepera-sim 0.1.0",
        description = "A deterministic Khepera robot simulator. Runs a controller class in an arena.",
        subcommands = {GuiCommand.class, GuiBenchCommand.class, RunCommand.class, BenchCommand.class, SettingsCommand.class,
            ListCommand.class, ServeCommand.class, ImportWsuCommand.class,
            CommandLine.HelpCommand.class})
public final class Main implements java.util.concurrent.Callable<Integer> {

    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    /** With no command: open the window with the defaults (maze, WallFollower). */
    @Override
    public Integer call() {
        return GuiCommand.open(org.kheperasim.sim.gui.GuiOptions.defaults());
    }

    /** @return a command line ready to execute, with the project's error handling */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        cl.setExecutionExceptionHandler((e, cmd, parsed) -> {
            cmd.getErr().println("khepera-sim: " + e.getMessage());
            if (e.getCause() != null && System.getenv("KHEPERA_DEBUG") != null) {
                e.printStackTrace(cmd.getErr());
            }
            return 2;
        });
        return cl;
    }

    /**
     * Runs the command line. The process exit status is the only way a script learns whether the
     * run succeeded, so a failure exits non-zero here, and only here.
     *
     * @param args command-line arguments
     */
    public static void main(String[] args) {
        int code = commandLine().execute(args);
        if (code != 0) {
            System.exit(code);
        }
    }
}
