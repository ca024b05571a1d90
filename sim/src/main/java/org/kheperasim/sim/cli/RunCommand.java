package org.kheperasim.sim.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ControllerOptions;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.grade.FailureLines;
import org.kheperasim.sim.grade.FailureText;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.BoundedConsole;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;
import org.kheperasim.sim.text.Shown;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code run}: one headless run, with its result (a line per robot when there are several) or a JSON object. */
@Command(name = "run", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Run a controller in an arena headless and print the result.",
            "A controller fails the run (exit status 1) when it throws, hangs, breaks a rule while it runs"
                    + " (System.exit, a shutdown hook, a wait nothing can end) or runs out of memory; a"
                    + " class that uses a forbidden call (files, the network: see docs/controller-rules.md) is refused"
                    + " before the run (exit status 2).",
            "With --trace the trace is written as the run goes (whole lines, at least every second), so a run"
                    + " that is killed leaves a readable trace; on SIGTERM (kill, Ctrl-C) the run stops, the trace is"
                    + " finished and the result line printed."})
final class RunCommand implements Callable<Integer> {
    /** Simulated seconds when --seconds is not given. */
    static final double DEFAULT_SECONDS = 600;

    @Option(names = "--arena", required = true, paramLabel = "FILE", completionCandidates = BundledArenas.class,
            description = "an arena file, or a bundled arena (${COMPLETION-CANDIDATES}; see list)")
    String arena;

    @Option(names = "--robot-file", paramLabel = "FILE",
            description = "the robot for the arena's robot lines that name none: a robot file or a bundled"
                    + " robot (see robots)")
    String robotFile;

    @Mixin
    ControllerOptions controllerOptions = new ControllerOptions();

    @Option(names = "--seed", paramLabel = "N", converter = CliNumbers.AnyLong.class,
            description = "the run's seed (default: a new one, printed)")
    Long seed;

    @Option(names = "--trusted",
            description = "run the controller uncontained: allow files, the network, reflection and System.exit (only"
                    + " for code you trust; see docs/controller-rules.md)")
    boolean trusted;

    @Option(names = "--trace", paramLabel = "FILE",
            description = "write a trace of the run (text, one line per sample)")
    Path trace;

    @Option(names = "--html", paramLabel = "FILE", description = "write the run as one web page that replays it in any"
            + " browser, with its failures and score (no server or network: docs/web-replay.md)")
    Path html;

    @Option(names = "--edits", paramLabel = "FILE",
            description = "apply the arena edits recorded in the window (run.edits) at their simulated times,"
                    + " replaying that run")
    Path edits;

    @Option(names = "--sample-ms", paramLabel = "MS", defaultValue = "50", converter = CliNumbers.PositiveLong.class,
            description = "trace sample period, whole ms (default: ${DEFAULT-VALUE})")
    long sampleMillis;

    @Mixin
    SettingsOptions settingsOptions = new SettingsOptions();

    @Option(names = "--hang-timeout", paramLabel = "SECONDS", defaultValue = "5",
            converter = CliNumbers.PositiveSeconds.class,
            description = "real seconds without an API call after which a controller counts as hung, > 0 (default:"
                    + " ${DEFAULT-VALUE})")
    double hangTimeout;

    @Option(names = "--robot", paramLabel = "N:KEY=VALUE",
            description = {"give robot N (0 for the arena's first robot line) its own controller or"
                    + " setting; repeatable:",
                "--robot 1:controller=Braitenberg --robot 1:motor.left.calibration=0.8 (KEY is 'controller' or a"
                        + " setting name from 'khepera-sim settings')"})
    List<String> robotOptions = new ArrayList<>();

    @Option(names = "--json", description = "print one JSON object with the result (messages go to standard error)")
    boolean json;

    @Option(names = "--quiet", description = "do not print the controller's messages")
    boolean quiet;

    @Option(names = "--sandbox",
            description = "run in an operating-system sandbox, as grade does: only the Java runtime,"
            + " the simulator, the controller's classpath and the arena visible, no network, limits on"
            + " processes, files, memory (Linux, bubblewrap; see docs/grading.md)")
    boolean sandbox;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws java.io.IOException {
        if (sandbox) {
            String c = controllerOptions.controller().strip();
            if (c.endsWith(".java") && java.nio.file.Files.isRegularFile(Path.of(c))) {
                throw new org.kheperasim.api.spi.ControllerException(
                        "--sandbox runs compiled classes, and " + c + " is a"
                        + " source: compile it first, javac -cp khepera-sim.jar -d out " + c
                        + ", then give --classpath out"
                        + " --controller " + Path.of(c).getFileName().toString().replaceFirst("\\.java$", ""));
            }
            return inTheBox();
        }
        Settings settings = settingsOptions.settings();
        PrintStream info = json ? System.err : System.out;
        Arena resolved = RobotFiles.arena(arena, robotFile);
        HtmlPage[] page = new HtmlPage[1]; // set once the run is configured; the console writes to it
        FailureLines failures = new FailureLines();
        EditLog editLog = edits == null ? null : EditLog.load(edits);
        SourceController.Compiled chosen =
                SourceController.of(controllerOptions.controller(), controllerOptions.classpath(),
                System.err);
        Simulation.Builder run = Simulation.builder()
                .arena(resolved)
                .controller(chosen.controller())
                .classpath(chosen.classpath())
                .trusted(trusted)
                .seconds(controllerOptions.seconds(resolved.assignment().secondsOr(DEFAULT_SECONDS)))
                .settings(settings)
                .sampleMillis(sampleMillis)
                .hostOptions(HostOptions.defaults().withHangTimeout((long) (hangTimeout * 1e9)))
                .console(line -> {
                    failures.seen(line);
                    if (page[0] != null) {
                        page[0].recorder().console(line);
                    }
                    if (line.kind() != ConsoleLine.Kind.MESSAGE) {
                        System.err.println(line.format());
                    } else if (!quiet) {
                        info.println(line.format());
                    }
                });
        robots(settings, run);
        if (seed != null) {
            run.seed(seed);
        }
        if (trace != null) {
            run.trace(trace);
        }
        if (editLog != null) {
            run.edits(editLog);
        }
        if (html != null) {
            page[0] = HtmlPage.attach(html, resolved, editLog, run);
        }
        info.println("seed " + run.seed());
        run.onStart(session -> info.println(session.modeLine()));
        return StopOnSignal.run(run, hangTimeout, result -> {
            int exit = report(result, score(result, resolved), failures);
            if (page[0] != null) {
                page[0].write(result, info);
            }
            return exit;
        });
    }

    /** The same command again, in a bubblewrap box (see sandbox.Reexec). */
    private int inTheBox() {
        List<String> args = absolutePaths(Sandboxed.argsAfter(spec, "run"));
        List<Path> read = new ArrayList<>(controllerOptions.classpath().stream().map(Path::toAbsolutePath).toList());
        java.nio.file.Path arenaFile = Path.of(arena);
        if (java.nio.file.Files.isRegularFile(arenaFile)) {
            read.add(arenaFile.toAbsolutePath());
        }
        if (edits != null) {
            read.add(edits.toAbsolutePath());
        }
        read.addAll(RobotFiles.files(arena, robotFile));
        List<Path> write = new ArrayList<>(trace == null ? List.of() : List.of(trace.toAbsolutePath()));
        HtmlPage.Boxed page = html == null ? null : new HtmlPage.Boxed(html, trace, args, write);
        Arena resolved = ArenaFormat.resolve(arena);
        int code = org.kheperasim.sim.sandbox.Reexec.run("run", args, read, write, false,
                org.kheperasim.sim.sandbox.BoxLimits.forCommand(resolved.robots().size()), hangTimeout + 5);
        if (page != null) {
            page.write(resolved, json ? System.err : System.out);
        }
        return code;
    }

    /** The options whose values are files: the box runs in a folder of its own, where a relative path names nothing. */
    private static final java.util.Set<String> PATH_OPTIONS =
            java.util.Set.of("--arena", "--classpath", "--trace", "--edits",
            "--robot-file");

    /** @return the arguments with each file option's value an absolute path ({@code --arena} only when it is a file) */
    static List<String> absolutePaths(List<String> args) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            int eq = a.indexOf('=');
            String name = eq > 0 ? a.substring(0, eq) : a;
            if (!PATH_OPTIONS.contains(name) || (eq < 0 && i + 1 >= args.size())) {
                out.add(a);
                continue;
            }
            String value = eq > 0 ? a.substring(eq + 1) : args.get(++i);
            StringBuilder abs = new StringBuilder();
            for (String part : value.split(java.util.regex.Pattern.quote(java.io.File.pathSeparator), -1)) {
                boolean file = !name.equals("--arena") && !name.equals("--robot-file")
                        || java.nio.file.Files.isRegularFile(Path.of(part));
                abs.append(abs.length() > 0 ? java.io.File.pathSeparator : "")
                        .append(file && !part.isEmpty() ? Path.of(part).toAbsolutePath().toString() : part);
            }
            out.addAll(List.of(name, abs.toString()));
        }
        return out;
    }

    private static Score score(RunResult result, Arena resolved) {
        return resolved.assignment().hasTasks() ? Score.of(resolved, RunFacts.of(result)) : null;
    }

    /** Apply the {@code --robot N:KEY=VALUE} options: a robot's own controller and settings. */
    private void robots(Settings base, Simulation.Builder run) {
        Map<Integer, String> controllers = new TreeMap<>();
        Map<Integer, Settings> own = new TreeMap<>();
        java.util.Set<String> given = new java.util.HashSet<>();
        for (String o : robotOptions) {
            int colon = o.indexOf(':');
            int eq = o.indexOf('=', colon + 1);
            int index;
            try {
                index = colon > 0 ? Integer.parseInt(o.substring(0, colon).strip()) : -1;
            } catch (NumberFormatException e) {
                index = -1;
            }
            if (index < 0 || eq < 0 || eq == colon + 1) {
                throw new IllegalArgumentException("--robot '" + o
                        + "': expected N:KEY=VALUE with N a robot's index from 0,"
                        + " e.g. --robot 1:controller=Braitenberg or --robot 1:motor.left.calibration=0.8");
            }
            String key = o.substring(colon + 1, eq).strip();
            String value = o.substring(eq + 1).strip();
            if (!given.add(index + ":" + key)) {
                throw new IllegalArgumentException("--robot '" + o + "': robot " + index + "'s " + key
                        + " is given twice; give it once");
            }
            if (key.equals("controller")) {
                controllers.put(index, value);
            } else if (Settings.wholeRun(key)) {
                throw new IllegalArgumentException("--robot '" + o + "': " + key + " is one setting for the whole run,"
                        + " not per robot; give it with --set " + key + "=" + value);
            } else {
                try {
                    own.put(index, own.getOrDefault(index, base).with(key, value));
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("--robot '" + o + "': " + e.getMessage(), e);
                }
            }
        }
        java.util.Set<Integer> robots = new java.util.TreeSet<>(controllers.keySet());
        robots.addAll(own.keySet());
        for (int i : robots) {
            run.robot(i, controllers.get(i), own.get(i));
        }
    }

    private int report(RunResult result, Score score, FailureLines failures) {
        System.out.println(json ? toJson(result, score, failures) : summary(result, score));
        System.out.flush();
        for (RunResult.RobotResult r : result.robots()) {
            if (r.status().failed()) {
                return ExitCodes.FAILED;
            }
        }
        return ExitCodes.OK;
    }

    static String summary(RunResult result) {
        return summary(result, null);
    }

    /**
     * @param score the run's score, or null when the arena has no tasks
     * @return the result: one line for a lone robot; with several, a line for the run and one per robot
     */
    static String summary(RunResult result, Score score) {
        boolean lone = result.robots().size() == 1;
        StringBuilder s = new StringBuilder(
                String.format(Locale.ROOT, "%s in %s: %.1f s simulated in %.2f s (%.0fx real time)",
                Shown.line(simpleName(result.controller())), Shown.line(result.arena()), result.simulatedSeconds(),
                result.wallSeconds(),
                result.realTimeFactor()));
        if (lone) {
            s.append("; ");
            robot(s, result.first());
        } else {
            s.append("; ").append(result.robots().size()).append(" robots");
        }
        if (result.caps() > 0) {
            s.append("; caps per region ").append(result.capsInRegions());
        }
        if (score != null) {
            s.append("; score ").append(score.summary());
        }
        if (result.traceSha256() != null) {
            s.append("; trace sha256 ").append(result.traceSha256());
        }
        if (!lone) {
            for (int i = 0; i < result.robots().size(); i++) {
                RunResult.RobotResult r = result.robots().get(i);
                s.append(System.lineSeparator()).append("  robot ").append(i).append(" (").append(Shown.line(r.name()))
                        .append("): ");
                robot(s, r);
            }
        }
        return s.toString();
    }

    private static void robot(StringBuilder s, RunResult.RobotResult r) {
        s.append(String.format(Locale.ROOT,
                "ended at (%.1f, %.1f) mm heading %.1f deg; travelled %.2f m; %d collisions;"
                + " visited %.1f%% of the floor", r.x(), r.y(), r.headingDeg(), r.distanceMm() / 1000, r.collisions(),
                r.visitedPercent()));
        s.append("; controller ").append(r.status().name().toLowerCase(Locale.ROOT));
    }

    static String toJson(RunResult result) {
        return toJson(result, null, new FailureLines());
    }

    /**
     * @param score    the run's score, or null when the arena has no tasks
     * @param failures the controllers' error lines seen during the run: a robot whose controller threw gets
     *                 {@code failureAt}, the student's line; one that failed {@code failureSeconds}, when, s
     * @return the JSON object
     */
    static String toJson(RunResult result, Score score, FailureLines failures) {
        RunResult.RobotResult first = result.first();
        Json j = new Json().begin()
                .put("seed", result.seed())
                .put("arena", result.arena())
                .put("controller", result.controller())
                .put("simulatedSeconds", result.simulatedSeconds())
                .put("wallSeconds", result.wallSeconds())
                .put("realTimeFactor", result.realTimeFactor());
        j.beginObject("finalPose").put("x", first.x()).put("y", first.y()).put("headingDeg", first.headingDeg()).end();
        j.put("distanceMm", first.distanceMm())
                .put("collisions", first.collisions())
                .put("visitedPercent", first.visitedPercent())
                .put("controllerStatus", first.status().name().toLowerCase(Locale.ROOT))
                .put("traceSha256", result.traceSha256())
                .put("regionsEntered", first.regionsEntered())
                .put("caps", result.caps())
                .put("capsInRegions", result.capsInRegions());
        j.beginArray("robots");
        for (RunResult.RobotResult r : result.robots()) {
            j.element().put("name", r.name())
                    .put("x", r.x()).put("y", r.y()).put("headingDeg", r.headingDeg())
                    .put("distanceMm", r.distanceMm()).put("collisions", r.collisions())
                    .put("visitedPercent", r.visitedPercent())
                    .put("controllerStatus", r.status().name().toLowerCase(Locale.ROOT))
                    .put("failure", BoundedConsole.bounded(r.failure()));
            if (r.status().failed()) {
                ConsoleLine thrown = failures.thrown(r.name());
                String at = thrown == null ? null : FailureText.studentFrame(thrown.text());
                if (at != null) {
                    j.put("failureAt", at);
                }
                ConsoleLine report = failures.first(r.name());
                if (report != null) {
                    j.put("failureSeconds", report.timeNanos() / 1e9);
                }
            }
            j.end();
        }
        j.endArray();
        if (score != null) {
            j.beginObject("score").put("points", score.points()).put("max", score.max())
                    .put("percent", score.percent());
            j.beginArray("tasks");
            for (Score.Part p : score.parts()) {
                j.element().put("task", p.task()).put("fraction", p.fraction()).put("points", p.points())
                        .put("max", p.max()).put("detail", p.detail()).end();
            }
            j.endArray().end();
        }
        return j.end().toString();
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
