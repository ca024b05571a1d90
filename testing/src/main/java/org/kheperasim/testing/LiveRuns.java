package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.testkit.KitContact;
import org.kheperasim.sim.testkit.KitResult;
import org.kheperasim.sim.testkit.TestKit;
import org.opentest4j.AssertionFailedError;

/**
 * Makes a run in the simulator, headless, and shapes what it produced for a test: the run's trace (kept
 * in memory), its result, its contacts (the engine's own events, at their ticks) and its console become a
 * {@link Run}. The run is the one {@code khepera-sim run --trace FILE} makes with the same options: the same
 * engine, the same controller loading and containment, the same trace bytes.
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
        RunCapture capture = new RunCapture();
        KitResult result;
        try {
            result = TestKit.run(spec.kit(), capture);
        } catch (ControllerException e) {
            String where = StudentLines.inText(e.getMessage()).map(w -> " (" + w + ")").orElse("");
            throw new AssertionFailedError("The controller could not run" + where + ": " + e.getMessage()
                    + "\n  run:      " + spec.commandLine(), e);
        }
        String text = result.trace();
        TraceSamples samples = TraceSamples.parse(text, "the run's trace");
        boolean lone = result.robots().size() == 1;
        List<RobotRun> robots = new ArrayList<>();
        for (int i = 0; i < result.robots().size(); i++) {
            KitResult.Robot r = result.robots().get(i);
            TraceSamples.Series s = samples.robots.get(i);
            Map<String, SimTime> entered = new LinkedHashMap<>();
            r.regionsEntered().forEach((name, t) -> entered.put(name, SimTime.ofSeconds(t)));
            Ending ending = ending(r, capture.firstError(r.name()), result.simulatedSeconds(), lone);
            robots.add(new RobotRun(i, r.name(), className(spec.controllers().get(i)), RunShapes.path(s),
                    contacts(r.contacts(), s), entered, ending, r.distanceMm(), r.collisions(), r.visitedPercent()));
        }
        return new Run(spec, null, SimTime.ofSeconds(result.simulatedSeconds()), robots,
                RunShapes.caps(samples, spec.arena()), RunShapes.score(result.score()), text, capture.console());
    }

    /** The engine's contacts; one that no sample of the trace falls within is marked as between samples. */
    private static List<Contact> contacts(List<KitContact> kit, TraceSamples.Series s) {
        List<Contact> out = new ArrayList<>(kit.size());
        for (KitContact c : kit) {
            int i = s.indexAt(c.toNanos());
            boolean seen = i >= 0 && s.nanos[i] >= c.fromNanos();
            out.add(new Contact(new SimTime(c.fromNanos()), new SimTime(c.toNanos()), RunShapes.obstacle(c.kind()),
                    c.side(), c.x(), c.y(), !seen));
        }
        return out;
    }

    /** How a robot's controller ended, from its status, what it failed with and the first error the console got. */
    private static Ending ending(KitResult.Robot r, Optional<RunCapture.Error> error, double endSeconds, boolean lone) {
        Optional<SimTime> end = Optional.of(SimTime.ofSeconds(endSeconds));
        KitResult.Status status = r.status();
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
                : TestKit.bundledControllers().contains(controller)
                        ? TestKit.bundledControllerPackage() + "." + controller : controller;
    }
}
