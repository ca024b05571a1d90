package org.kheperasim.sim.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerHost;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code run}: one headless run, with a one-line result or a JSON object. */
@Command(name = "run", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Run a controller in an arena headless and print the result.",
            "Exit status: 0 when the controller ran to the end, 1 when it threw, hung, broke a rule (System.exit, a forbidden call) or ran out of memory, 2 for bad input."})
final class RunCommand implements Callable<Integer> {

    @Option(names = "--arena", required = true, paramLabel = "FILE",
            description = "an arena file, or a bundled arena (lab, maze, two-rooms; see list)")
    String arena;

    @Option(names = "--controller", required = true, paramLabel = "NAME",
            description = "a bundled controller (WallFollower, Braitenberg, Template) or a class name on --classpath")
    String controller;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controller classes, as with java -cp")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--seed", paramLabel = "N", description = "the run's seed (default: a new one, printed)")
    Long seed;

    @Option(names = "--seconds", paramLabel = "T", defaultValue = "600",
            description = "simulated seconds to run (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--trace", paramLabel = "FILE", description = "write a trace of the run (text, one line per sample)")
    Path trace;

    @Option(names = "--edits", paramLabel = "FILE",
            description = "apply the arena edits recorded in the window (run.edits) at their simulated times, replaying that run")
    Path edits;

    @Option(names = "--sample-ms", paramLabel = "MS", defaultValue = "50",
            description = "trace sample period, ms (default: ${DEFAULT-VALUE})")
    long sampleMillis;



    @Mixin
    SettingsOptions settingsOptions = new SettingsOptions();

    @Option(names = "--hang-timeout", paramLabel = "SECONDS", defaultValue = "5",
            description = "real seconds without an API call after which a controller counts as hung (default: ${DEFAULT-VALUE})")
    double hangTimeout;

    @Option(names = "--json", description = "print one JSON object with the result (messages go to standard error)")
    boolean json;

    @Option(names = "--quiet", description = "do not print the controller's messages")
    boolean quiet;

    @Override
    public Integer call() {
        Settings settings = settingsOptions.settings();
        PrintStream info = json ? System.err : System.out;
        Simulation.Builder run = Simulation.builder()
                .arena(arena)
                .controller(controller)
                .classpath(classpath)
                .seconds(seconds)
                .settings(settings)
                .sampleMillis(sampleMillis)
                .hostOptions(ControllerHost.Options.defaults().withHangTimeout((long) (hangTimeout * 1e9)))
                .console(line -> {
                    if (line.kind() != ConsoleLine.Kind.MESSAGE) {
                        System.err.println(line.format());
                    } else if (!quiet) {
                        info.println(line.format());
                    }
                });
        if (seed != null) {
            run.seed(seed);
        }
        if (trace != null) {
            run.trace(trace);
        }
        if (edits != null) {
            run.edits(org.kheperasim.sim.run.EditLog.load(edits));
        }
        info.println("seed " + run.seed());
        RunResult result = run.run();
        if (json) {
            System.out.println(toJson(result));
        } else {
            System.out.println(summary(result));
        }
        for (RunResult.RobotResult r : result.robots()) {
            if (r.status().failed()) {
                return 1;
            }
        }
        return 0;
    }

    static String summary(RunResult result) {
        RunResult.RobotResult r = result.first();
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT,
                "%s in %s: %.1f s simulated in %.2f s (%.0fx real time); ended at (%.1f, %.1f) mm heading %.1f deg;"
                        + " travelled %.2f m; %d collisions; visited %.1f%% of the floor",
                simpleName(result.controller()), result.arena(), result.simulatedSeconds(), result.wallSeconds(),
                result.realTimeFactor(), r.x(), r.y(), r.headingDeg(), r.distanceMm() / 1000, r.collisions(),
                r.visitedPercent()));
        s.append("; controller ").append(r.status().name().toLowerCase(Locale.ROOT));
        if (result.caps() > 0) {
            s.append("; caps per region ").append(result.capsInRegions());
        }
        if (result.traceSha256() != null) {
            s.append("; trace sha256 ").append(result.traceSha256());
        }
        return s.toString();
    }

    static String toJson(RunResult result) {
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
                    .put("failure", r.failure())
                    .end();
        }
        j.endArray();
        return j.end().toString();
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
