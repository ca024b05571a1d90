package org.kheperasim.testfixtures;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import org.kheperasim.sim.cli.Main;

/** The simulator's command line run in this JVM, with what it printed: for tests of what a user sees. */
public final class Cli {
    /**
     * What one command did.
     *
     * @param code its exit status
     * @param out  what it printed on standard output
     * @param err  what it printed on standard error
     */
    public record Printed(int code, String out, String err) {
    }

    private Cli() {
    }

    /**
     * @param args the command line, as after {@code java -jar khepera-sim.jar}
     * @return its exit status and output (System.out and System.err are caught too: a controller prints there)
     */
    public static Printed main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            var cl = Main.commandLine();
            cl.setOut(new PrintWriter(System.out, true));
            cl.setErr(new PrintWriter(System.err, true));
            code = cl.execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        return new Printed(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
    }
}
