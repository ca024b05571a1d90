package org.kheperasim.testing;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.RunFacts;
import org.opentest4j.AssertionFailedError;

/**
 * Makes a run in the simulator, headless, and shapes what it produced for a test: the run's trace (kept
 * in memory), its result and its console become a {@link Run}. The run is the one {@code khepera-sim run
 * --trace FILE} makes with the same options: the same engine, the same controller loading and
 * containment, the same trace bytes.
 */
final class LiveRuns {
    private LiveRuns() {
    }

    /**
     * @param spec what to run
     * @return what happened
     * @throws AssertionFailedError when a controller cannot run at all (refused for a forbidden call, or its
     *     constructor threw), naming it and the student's line
     */
    static Run run(RunSpec spec) {
        StringWriter trace = new StringWriter();
        RunCapture capture = new RunCapture();
        RunResult result;
        try {
            result = spec.simulation(trace, capture).run();
        } catch (ControllerException e) {
            String where = StudentLines.inText(e.getMessage()).map(w -> " (" + w + ")").orElse("");
            throw new AssertionFailedError("The controller could not run" + where + ": " + e.getMessage()
                    + "\n  run:      " + spec.commandLine(), e);
        }
        String text = trace.toString();
        TraceSamples samples = TraceSamples.parse(text, "the run's trace");
        ContactFinder finder = new ContactFinder(samples, t -> spec.arena());
        boolean lone = result.robots().size() == 1;
        List<RobotRun> robots = new ArrayList<>();
        for (int i = 0; i < result.robots().size(); i++) {
            RunResult.RobotResult r = result.robots().get(i);
            TraceSamples.Series s = samples.robots.get(i);
            int[] collisions = capture.collisionsAt(i, s.nanos, s.size, r.collisions());
            Map<String, SimTime> entered = new LinkedHashMap<>();
            r.regionsEntered().forEach((name, t) -> entered.put(name, SimTime.ofSeconds(t)));
            Ending ending = ending(r, capture.firstError(r.name()), result.simulatedSeconds(), lone);
            robots.add(new RobotRun(i, r.name(), className(spec.controllers().get(i)), RunShapes.path(s),
                    finder.contacts(i, collisions), entered, ending, r.distanceMm(), r.collisions(), r.visitedPercent()));
        }
        Score score = RunShapes.score(org.kheperasim.sim.task.Score.of(spec.arena(), RunFacts.of(result)));
        return new Run(spec, null, SimTime.ofSeconds(result.simulatedSeconds()), robots,
                RunShapes.caps(samples, spec.arena()), score, text, capture.console());
    }

    /** How a robot's controller ended, from its status, what it failed with and the first error the console got. */
    private static Ending ending(RunResult.RobotResult r, Optional<RunCapture.Error> error, double endSeconds, boolean lone) {
        Optional<SimTime> end = Optional.of(SimTime.ofSeconds(endSeconds));
        ControllerStatus status = r.status();
        Ending.Kind kind = switch (status) {
            case FINISHED -> Ending.Kind.RETURNED;
            case FAILED -> Ending.Kind.THREW;
            case HUNG -> Ending.Kind.HUNG;
            case BROKE_RULE -> Ending.Kind.BROKE_A_RULE;
            case EXCEEDED_MEMORY -> Ending.Kind.OUT_OF_MEMORY;
            case NOT_STARTED, RUNNING, STOPPED -> Ending.Kind.RAN_TO_THE_END;
        };
        if (kind == Ending.Kind.RAN_TO_THE_END) {
            return new Ending(kind, end, "", Optional.empty());
        }
        if (kind == Ending.Kind.RETURNED) {
            // A lone robot's run ends when its controller does; with several, the others go on.
            return new Ending(kind, lone ? end : Optional.empty(), "", Optional.empty());
        }
        String message = error.map(RunCapture.Error::text).orElse(r.failure() == null ? status.name() : r.failure());
        return new Ending(kind, error.map(e -> new SimTime(e.nanos())).or(() -> end), message,
                error.flatMap(RunCapture.Error::where).or(() -> StudentLines.inText(r.failure())));
    }

    /** A bundled controller's simple name as its class name. */
    private static String className(String controller) {
        return controller.contains(".") ? controller
                : org.kheperasim.sim.run.ControllerCatalog.bundled().contains(controller)
                        ? org.kheperasim.sim.run.ControllerCatalog.BUNDLED_PACKAGE + "." + controller : controller;
    }
}
