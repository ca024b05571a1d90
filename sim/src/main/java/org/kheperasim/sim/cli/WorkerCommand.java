package org.kheperasim.sim.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.kheperasim.sim.grade.worker.WorkerLoop;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code worker}: a warm worker JVM of {@code grade} (hidden; the grader starts it, in the sandbox):
 * it makes one submission's runs one after another, each exactly as {@code run --command-log}
 * makes it in a JVM of its own, taking the requests from standard input (docs/grading.md, "Warm
 * workers"; the protocol is grade.worker.WorkerProtocol's).
 */
@Command(name = "worker", hidden = true, description = "A warm worker JVM of grade (started by grade, not by hand).")
final class WorkerCommand implements Callable<Integer> {
    @Option(names = "--classpath", required = true, paramLabel = "DIR", description = "the submission's classes")
    Path classpath;

    @Option(names = "--scratch", required = true, paramLabel = "DIR", description = "the runs' working folder")
    Path scratch;

    @Override
    public Integer call() {
        WorkerLoop.Launcher launcher = WorkerCommand::run;
        WorkerLoop.serve(launcher, scratch, classpath.toString(), () -> run(List.of("--arena", "lab", "--controller",
                "StepBraitenberg", "--seconds", "1", "--seed", "1", "--quiet", "--json")));
        return 0;
    }

    /** {@code run} with these arguments, as a child JVM's main would make it; its exit status. */
    private static int run(List<String> args) {
        List<String> all = new ArrayList<>();
        all.add("run");
        all.addAll(args);
        String[] a = all.toArray(String[]::new);
        return Main.commandLineFor(a).execute(a);
    }
}
