package org.kheperasim.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.kheperasim.sim.testkit.KitFailure;
import org.kheperasim.sim.testkit.TestKit;

/**
 * Writes a run's files for a person to look at: the trace, the arena beside it (so that the window's
 * File &gt; Open recording and {@code khepera-sim verify} find it by the name and SHA-256 the trace records),
 * and a text file with the command that makes the run again, how to watch it, and the run's console.
 */
final class RunFiles {
    /** The trace files runs of this JVM have written, so two runs of one test do not overwrite each other's. */
    private static final Set<Path> CLAIMED = ConcurrentHashMap.newKeySet();

    private RunFiles() {
    }

    /**
     * @param run a run
     * @param folder where to write
     * @return the trace file
     */
    static Path save(Run run, Path folder) {
        Path trace = run.savedTrace().filter(t -> t.toAbsolutePath().getParent().equals(folder.toAbsolutePath()))
                .orElse(null);
        String base = TestRuns.safe(run.arena() + "-" + simpleName(run.robot().controller()) + "-seed" + run.seed());
        for (int i = 1; trace == null; i++) {
            Path candidate = folder.resolve(base + (i == 1 ? "" : "-" + i) + ".trace");
            if (CLAIMED.add(candidate.toAbsolutePath())) {
                trace = candidate;
            }
        }
        String name = trace.getFileName().toString().replaceFirst("\\.trace$", "");
        try {
            Files.createDirectories(folder);
            TestKit.writeAtomically(trace, run.trace());
            TestKit.saveArena(run.spec().arena(), folder);
            run.saved(trace);
            // The run as a web page beside the trace, to watch in a browser (no simulator needed).
            TestKit.writeRunPage(trace, run.spec().arena(), run.toString(), failures(run), page(trace));
            TestKit.writeAtomically(folder.resolve(name + ".txt"), about(run, trace));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the run's files in " + folder.toAbsolutePath() + ": "
                    + e.getMessage(), e);
        }
        return trace;
    }

    /** @return the web page written beside {@code trace} */
    static Path page(Path trace) {
        return trace.resolveSibling(trace.getFileName().toString().replaceFirst("\\.trace$", "") + ".html");
    }

    /** What the page shows beyond the samples and its heading: how each controller that failed ended. */
    private static List<KitFailure> failures(Run run) {
        List<KitFailure> failures = new ArrayList<>();
        for (int i = 0; i < run.robots().size(); i++) {
            Ending e = run.robots().get(i).ending();
            if (!e.normal() && e.kind() != Ending.Kind.NOT_RECORDED) {
                failures.add(new KitFailure(i, e.at().map(SimTime::seconds).orElse(Double.NaN),
                        e.kind().name().toLowerCase(Locale.ROOT).replace('_', ' '), e.toString()));
            }
        }
        return failures;
    }

    /** The text beside a trace: what the run was, how to watch it and make it again, and its console. */
    private static String about(Run run, Path trace) {
        String shown = RunSpec.shown(trace);
        StringBuilder s = new StringBuilder();
        s.append(run).append('\n').append('\n');
        s.append("Watch it in a browser: open ").append(RunSpec.shown(page(trace))).append('\n');
        s.append("Or in the simulator's window: start it (java -jar khepera-sim.jar), choose File > Open recording\n")
                .append("and open ").append(shown).append('\n');
        s.append("Make the same run again (the simulator is deterministic: add --trace FILE for the same trace, byte"
                + " for byte):\n  ")
                .append(run.commandLine()).append('\n');
        s.append("Check that it still comes out the same:\n  java -jar khepera-sim.jar verify ").append(shown);
        if (!run.spec().classpath().isEmpty()) {
            s.append(" --classpath ").append(String.join(java.io.File.pathSeparator,
                    run.spec().classpath().stream().map(RunSpec::shown).toList()));
        }
        s.append('\n');
        for (RobotRun r : run.robots()) {
            s.append('\n').append(r).append("; controller ").append(r.ending());
            if (!r.contacts().isEmpty()) {
                s.append("; ").append(r.contacts().size()).append(" contacts, the first ").append(r.contacts().get(0));
            }
        }
        s.append('\n');
        if (!run.console().isEmpty()) {
            s.append("\nConsole:\n");
            run.console().forEach(line -> s.append(line).append('\n'));
        }
        return s.toString();
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
