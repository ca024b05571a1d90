package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.commandlog.CommandLogWriter;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * One graded run, the entry point of a graded child JVM ({@code java -cp SIMULATOR GradedRun ARGS}) and what
 * a warm worker makes for each request ({@link WorkerMain}): it connects to the grader's channel
 * before any controller class is loaded ({@link ChildSide}), builds the run as {@code eval.Evaluator}
 * does (a {@link Simulation} of one arena, one submission's controller, one seed, the default
 * settings), records its command log into the channel, and hands over its own result ({@link Claim})
 * and exit status: 0 when every controller ended well, 1 when one failed, 2 for a run that could not
 * be made (a class refused at load, a bad arena), with the reason on standard error, one line
 * {@code khepera-sim: error: ...} as the command line's.
 *
 * <p>The grader alone starts it; its arguments ({@link Args}) are the grader's, never a user's.
 */
public final class GradedRun {
    /** The main class of a graded run's JVM. */
    public static final String MAIN = GradedRun.class.getName();
    /** Simulated seconds of an arena without a time limit. */
    static final double DEFAULT_SECONDS = 600;

    /**
     * A graded run's arguments, {@code --name value} pairs (and the flag {@code --trusted}).
     *
     * @param arena        an arena file (absolute) or a bundled arena's name
     * @param classpath    the submission's classes
     * @param controller   the controller class
     * @param seed         the seed
     * @param hangSeconds  real seconds without an API call after which a controller counts as hung
     * @param sampleMillis the trace's sample period, ms
     * @param channel      the grader's socket for the command log
     * @param wallSeconds  the run's own wall-clock limit, s (0: none)
     * @param seconds      simulated seconds, or null for the arena's own
     * @param trusted      true to run the controller uncontained (tests of the sandbox only)
     */
    record Args(String arena, Path classpath, String controller, long seed, double hangSeconds, long sampleMillis,
            Path channel, double wallSeconds, Double seconds, boolean trusted) {

        /** @return the arguments as a list, as {@link #parse} reads them back */
        List<String> toList() {
            List<String> a = new ArrayList<>(
                    List.of("--arena", arena, "--classpath", classpath.toString(), "--controller",
                    controller, "--seed", Long.toString(seed), "--hang-timeout",
                    ChildRun.format(hangSeconds), "--sample-ms",
                    Long.toString(sampleMillis), "--command-log", channel.toString(), "--wall-limit",
                    ChildRun.format(wallSeconds)));
            if (seconds != null) {
                a.addAll(List.of("--seconds", ChildRun.format(seconds)));
            }
            if (trusted) {
                a.add("--trusted");
            }
            return a;
        }

        /**
         * @param args what {@link #toList} wrote
         * @return the arguments
         * @throws IllegalArgumentException if one is missing, unknown or not a number
         */
        static Args parse(List<String> args) {
            String arena = null;
            String classpath = null;
            String controller = null;
            String channel = null;
            long seed = 0;
            double hang = 5;
            long sample = 50;
            double wall = 0;
            Double seconds = null;
            boolean trusted = false;
            for (int i = 0; i < args.size(); i++) {
                String name = args.get(i);
                if (name.equals("--trusted")) {
                    trusted = true;
                    continue;
                }
                if (i + 1 >= args.size()) {
                    throw new IllegalArgumentException("graded run: " + name + " needs a value");
                }
                String v = args.get(++i);
                try {
                    switch (name) {
                        case "--arena" -> arena = v;
                        case "--classpath" -> classpath = v;
                        case "--controller" -> controller = v;
                        case "--command-log" -> channel = v;
                        case "--seed" -> seed = Long.parseLong(v);
                        case "--hang-timeout" -> hang = Double.parseDouble(v);
                        case "--sample-ms" -> sample = Long.parseLong(v);
                        case "--wall-limit" -> wall = Double.parseDouble(v);
                        case "--seconds" -> seconds = Double.parseDouble(v);
                        default -> throw new IllegalArgumentException("graded run: unknown argument " + name);
                    }
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("graded run: " + name + " " + v + " is not a number", e);
                }
            }
            if (arena == null || classpath == null || controller == null || channel == null) {
                throw new IllegalArgumentException(
                        "graded run: --arena, --classpath, --controller and --command-log are"
                        + " needed (the grader starts graded runs; see docs/grading.md)");
            }
            return new Args(arena, Path.of(classpath), controller, seed, hang, sample, Path.of(channel), wall, seconds,
                    trusted);
        }
    }

    private GradedRun() {
    }

    /**
     * A graded child JVM: the run, then the JVM ends with its exit status ({@link ChildSide#finish} ends it
     * once the result is handed over).
     *
     * @param args the grader's arguments ({@link Args})
     */
    public static void main(String[] args) {
        int code = run(List.of(args));
        System.out.flush();
        System.err.flush();
        Runtime.getRuntime().halt(code);
    }

    /**
     * Make one graded run in this JVM.
     *
     * @param args the grader's arguments ({@link Args})
     * @return the exit status its JVM ends with: 0, 1 (a controller failed) or 2 (the run could not be made)
     */
    public static int run(List<String> args) {
        PrintStream err = System.err;
        try {
            Args a = Args.parse(args);
            // First of all, before any controller class is loaded: the channel a controller's code cannot name.
            ChildSide child = ChildSide.start(a.channel(), a.wallSeconds());
            Arena arena = ArenaFormat.resolve(a.arena());
            FailureLines failures = new FailureLines();
            Simulation.Builder run = Simulation.builder().arena(arena).controller(a.controller())
                    .classpath(List.of(a.classpath())).trusted(a.trusted())
                    .seconds(a.seconds() != null ? a.seconds() : arena.assignment().secondsOr(DEFAULT_SECONDS))
                    .settings(Settings.defaults()).sampleMillis(a.sampleMillis()).seed(a.seed())
                    .hostOptions(HostOptions.defaults().withHangTimeout((long) (a.hangSeconds() * 1e9)))
                    .console(line -> {
                        failures.seen(line);
                        // A controller's messages are no result of anything; its errors and the simulator's reports
                        // are what the grader reads when there is no whole log (ChildResults).
                        if (line.kind() != ConsoleLine.Kind.MESSAGE) {
                            err.println(line.format());
                        }
                    });
            long endNanos = (long) StrictMath.rint(run.seconds() * 1e9);
            // The trace is only hashed, for the result the grader checks against its replay.
            run.trace(Writer.nullWriter()).record(child.log())
                    .onStart(session -> child.started(session, endNanos, a.sampleMillis()));
            RunResult result = run.run();
            Score score = arena.assignment().hasTasks() ? Score.of(arena, RunFacts.of(result)) : null;
            int exit = result.robots().stream().anyMatch(r -> r.status().failed()) ? ExitCodes.FAILED : ExitCodes.OK;
            child.finish(Claim.of(result, score, failures), exit, result);
            return exit;
        } catch (IOException | RuntimeException e) {
            int code = ToolErrors.exitCode(e);
            String what = e.getMessage() == null ? e.toString() : e.getMessage();
            err.println(ToolErrors.prefix("khepera-sim") + (code == ExitCodes.FAILED ? "unexpected " + e : what));
            err.flush();
            return code;
        }
    }

    /**
     * A run of the simulator's own, as a graded run makes it but with nothing to hand over: a warm
     * worker makes it first, so that what the simulator starts once for all its runs is there before any
     * run is watched.
     */
    static void warmUp() {
        Arena lab = ArenaFormat.resolve("lab");
        Simulation.Builder run = Simulation.builder().arena(lab).controller("StepBraitenberg").seconds(1).seed(1)
                .settings(Settings.defaults()).sampleMillis(Grader.SAMPLE_MILLIS).console(line -> { });
        CommandLogWriter log = new CommandLogWriter(Writer.nullWriter());
        run.trace(Writer.nullWriter()).record(log).onStart(session -> log.start(
                org.kheperasim.sim.commandlog.LogHeader.of(session, 1_000_000_000L, Grader.SAMPLE_MILLIS)));
        RunResult result = run.run();
        try {
            log.finish(String.format(Locale.ROOT, "{\"simulatedSeconds\":%s}", result.simulatedSeconds()));
        } catch (IOException e) {
            // nothing is written anywhere
        }
    }
}
