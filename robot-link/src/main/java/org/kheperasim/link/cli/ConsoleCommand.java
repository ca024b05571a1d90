package org.kheperasim.link.cli;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code console}: type raw protocol lines, see the replies. */
@Command(name = "console", mixinStandardHelpOptions = true,
        description = "Type protocol lines (e.g. N, D,3,3, T,1,G) and see the robot's replies."
        + " An empty line or end of input quits; the robot is sent D,0,0 on the way out.")
final class ConsoleCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    Connection connection;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        try (Session session = connection.open(out)) {
            try {
                Session.Versions v = session.open();
                out.println("robot answers: BIOS " + v.bios() + ", protocol " + v.protocol());
            } catch (SessionException e) {
                out.println("warning: " + e.getMessage());
            }
            out.println("type a command and Enter; an empty line quits");
            out.flush();
            Thread hook = new Thread(() -> session.sendBlind(session.dialect().setSpeeds(0, 0)),
                    "khepera-stop-on-exit");
            session.link().addExitHook(hook);
            try {
                BufferedReader in = new BufferedReader(new InputStreamReader(Main.in, StandardCharsets.UTF_8));
                for (String line; (line = in.readLine()) != null && !line.isBlank(); ) {
                    long start = System.nanoTime();
                    List<String> replies = session.raw(line.strip(), 50, 2000);
                    double ms = (System.nanoTime() - start) / 1e6;
                    if (replies.isEmpty()) {
                        out.println(String.format(Locale.ROOT, "  (no reply in %.0f ms)", ms));
                    }
                    for (String r : replies) {
                        out.println("< " + r);
                    }
                    out.flush();
                }
            } finally {
                try {
                    session.exchange(session.dialect().setSpeeds(0, 0));
                    out.println("sent D,0,0; bye");
                } catch (SessionException e) {
                    session.sendBlind(session.dialect().setSpeeds(0, 0));
                    out.println("sent D,0,0 without an answer (" + e.getMessage() + "): check the robot has stopped");
                }
                out.flush();
                session.link().removeExitHook(hook);
            }
        }
        return 0;
    }
}
