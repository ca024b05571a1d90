package org.kheperasim.sim.grade;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.kheperasim.sim.host.ConsoleLine;

/**
 * The simulator's first report of each controller's failure, as the run's console gave it: its
 * simulated time and, for a throw, the student's part of the stack trace, which the run's result does
 * not hold (it has the exception's text only). Lines come from the controllers' threads. {@code run} and a
 * graded run ({@link GradedRun}) both read them.
 */
public final class FailureLines {
    private final Map<String, ConsoleLine> thrown = new ConcurrentHashMap<>();
    private final Map<String, ConsoleLine> first = new ConcurrentHashMap<>();

    /**
     * @param line a console line; a robot's first error that reads as a throw with its stack trace is
     *     kept (a controller's own {@code System.err} lines come one line at a time), and its first
     *     error that reads as the simulator's (a throw, or {@code controller Name ... stopped making API calls})
     */
    public void seen(ConsoleLine line) {
        if (line.kind() != ConsoleLine.Kind.ERROR) {
            return;
        }
        boolean throwReport = line.text().contains("\n") && line.text().contains("threw ");
        if (throwReport) {
            thrown.putIfAbsent(line.source(), line);
        }
        if (throwReport || line.text().startsWith("controller ")) {
            first.putIfAbsent(line.source(), line);
        }
    }

    /** @param robot a robot's name @return the report of its controller's throw, or null */
    public ConsoleLine thrown(String robot) {
        return thrown.get(robot);
    }

    /** @param robot a robot's name @return the simulator's first report of its controller's failure, or null */
    public ConsoleLine first(String robot) {
        return first.get(robot);
    }
}
