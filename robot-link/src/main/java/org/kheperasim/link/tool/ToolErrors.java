package org.kheperasim.link.tool;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.link.session.SessionException;
import picocli.CommandLine;

/**
 * How both tools report a failure: one line {@code TOOL: error: what is wrong and the fix} on
 * standard error, and the exit status of {@link ExitCodes}. Bad options, files, names and
 * connections exit {@link ExitCodes#BAD_INPUT}; anything else is a failure of the run or of the tool
 * ({@link ExitCodes#FAILED}), with the stack trace when {@code KHEPERA_DEBUG} is set.
 */
public final class ToolErrors {

    private ToolErrors() {
    }

    /**
     * @param tool the tool's name, e.g. {@code khepera-sim}
     * @return the prefix of every error line, e.g. {@code khepera-sim: error: }
     */
    public static String prefix(String tool) {
        return tool + ": error: ";
    }

    /**
     * Installs the error handling and the exit-code footer on a command line and its subcommands.
     *
     * @param cl   the command line
     * @param tool the tool's name, as it prefixes errors
     * @return {@code cl}
     */
    public static CommandLine install(CommandLine cl, String tool) {
        cl.setParameterExceptionHandler((ex, args) -> {
            CommandLine cmd = ex.getCommandLine();
            PrintWriter err = cmd.getErr();
            err.println(prefix(tool) + ex.getMessage());
            CommandLine.UnmatchedArgumentException.printSuggestions(ex, err);
            err.println("See '" + cmd.getCommandSpec().qualifiedName() + " --help' for the options.");
            err.flush();
            return ExitCodes.BAD_INPUT;
        });
        cl.setExecutionExceptionHandler((e, cmd, parsed) -> {
            PrintWriter err = cmd.getErr();
            int code = exitCode(e);
            String what = e.getMessage() == null ? e.toString() : e.getMessage();
            if (code == ExitCodes.FAILED) {
                what = "unexpected " + e
                        + "; this is a bug, please report it (set KHEPERA_DEBUG=1 for the stack trace)";
            }
            err.println(prefix(tool) + what);
            if (System.getenv("KHEPERA_DEBUG") != null) {
                e.printStackTrace(err);
            }
            err.flush();
            return code;
        });
        addFooter(cl);
        return cl;
    }

    /**
     * @param e what a command threw
     * @return {@link ExitCodes#BAD_INPUT} for what the user can fix (a bad value, file, name or
     *     connection), else {@link ExitCodes#FAILED}
     */
    public static int exitCode(Throwable e) {
        if (e instanceof IllegalArgumentException || e instanceof IOException || e instanceof UncheckedIOException
                || e instanceof ControllerException || e instanceof SessionException) {
            return ExitCodes.BAD_INPUT;
        }
        return ExitCodes.FAILED;
    }

    private static void addFooter(CommandLine cl) {
        cl.getCommandSpec().usageMessage().footer(ExitCodes.HELP);
        for (CommandLine sub : cl.getSubcommands().values()) {
            if (!(sub.getCommand() instanceof CommandLine.HelpCommand)) {
                addFooter(sub);
            }
        }
    }
}
