package org.kheperasim.link.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import org.kheperasim.link.robot.PollBench;
import org.kheperasim.link.session.Session;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import org.kheperasim.link.tool.CliNumbers;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code bench}: the poll rate this link reaches. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Poll the robot (N, O, H) as fast as the link allows for a while and print"
        + " the rate reached next to the timing model's prediction. The wheels stay still.")
final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    Connection connection;

    @Option(names = "--seconds", defaultValue = "5", converter = CliNumbers.PositiveSeconds.class,
            description = "How long to poll, seconds. Default: ${DEFAULT-VALUE}.")
    double seconds;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        try (Session session = connection.open(out)) {
            session.open();
            PollBench.Result r = PollBench.measure(session, connection.baud(), (long) (seconds * 1000));
            out.println(r.describe());
            out.flush();
            return 0;
        }
    }
}
