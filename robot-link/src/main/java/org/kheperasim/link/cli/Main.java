package org.kheperasim.link.cli;

import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.link.tool.ToolVersion;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Spec;

/** {@code java -jar khepera-link.jar}: drive a real Khepera over a serial port with a simulator controller. */
@Command(name = "khepera-link", mixinStandardHelpOptions = true, versionProvider = ToolVersion.class,
        description = "Runs the simulator's controllers on a real Khepera over a serial port (or TCP).",
        subcommands = {PortsCommand.class, RunCommand.class, ConsoleCommand.class, CheckCommand.class,
                BenchCommand.class, CalibrateCommand.class})
public final class Main implements Runnable {
    static {
        org.kheperasim.link.tool.PicocliStartup.skipUnusedConverters();
    }
    @Spec
    CommandLine.Model.CommandSpec spec;

    /** Standard input for the console; tests replace it. */
    static InputStream in = System.in;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /**
     * Run a command line with the given streams (tests use this; {@link #main} uses the console's).
     *
     * @param args the arguments
     * @param input standard input (the console command reads it)
     * @param out standard output
     * @param err standard error
     * @return the exit code ({@link ExitCodes}): 0 ok, 1 the run or check failed, 2 a usage or connection error
     */
    public static int execute(String[] args, InputStream input, PrintWriter out, PrintWriter err) {
        in = input;
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(out);
        cl.setErr(err);
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        ToolErrors.install(cl, "khepera-link");
        int code = cl.execute(args);
        out.flush();
        err.flush();
        return code;
    }

    /** @param args the command line */
    public static void main(String[] args) {
        int code = execute(args, System.in, new PrintWriter(System.out, true, StandardCharsets.UTF_8),
                new PrintWriter(System.err, true, StandardCharsets.UTF_8));
        if (code != 0) {
            System.exit(code);
        }
    }
}
