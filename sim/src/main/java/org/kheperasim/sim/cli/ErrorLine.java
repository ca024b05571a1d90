package org.kheperasim.sim.cli;

import java.io.PrintWriter;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.text.Shown;
import picocli.CommandLine;

/**
 * The simulator's error line, {@code khepera-sim: error: what is wrong and the fix}, as robot-link's
 * {@link ToolErrors} writes it and with the same exit codes, but always one line: a message holds
 * what a controller wrote (its exception's message, its class's name), so its control characters
 * and line ends are shown escaped ({@link Shown#visible}: a backslash stays one, as in a Windows path). An
 * {@link OutOfMemoryError}, which picocli does not catch, gets the line too.
 */
final class ErrorLine {
    static final String TOOL = "khepera-sim";

    private ErrorLine() {
    }

    /**
     * @param cl a command line with {@link ToolErrors} installed (and its subcommands added)
     * @return {@code cl}, its execution errors written as one line each
     */
    static CommandLine install(CommandLine cl) {
        cl.setExecutionExceptionHandler((e, cmd, parsed) -> {
            PrintWriter err = cmd.getErr();
            int code = ToolErrors.exitCode(e);
            String what = e.getMessage() == null ? e.toString() : e.getMessage();
            if (code == ExitCodes.FAILED) {
                what = "unexpected " + e
                        + "; this is a bug, please report it (set KHEPERA_DEBUG=1 for the stack trace)";
            }
            err.println(ToolErrors.prefix(TOOL) + Shown.visible(what));
            if (System.getenv("KHEPERA_DEBUG") != null) {
                e.printStackTrace(err);
            }
            err.flush();
            return code;
        });
        return cl;
    }

    /**
     * @param e the memory a command ran out of
     * @return the exit status, after the line on standard error
     */
    static int outOfMemory(OutOfMemoryError e) {
        System.err.println(ToolErrors.prefix(TOOL) + "out of memory (" + Shown.visible(e.getMessage())
                + "); give Java more"
                + " with java -Xmx4g -jar khepera-sim.jar ..., or a smaller input");
        if (System.getenv("KHEPERA_DEBUG") != null) {
            e.printStackTrace();
        }
        return ExitCodes.FAILED;
    }
}
