package org.kheperasim.sim.cli;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.kheperasim.sim.host.ConsoleLine;

/**
 * The simulator's report of each controller that threw, as the run's console gave it: its time and
 * the student's part of the stack trace, which the run's result does not hold (it has the exception's
 * text only). Lines come from the controllers' threads.
 */
final class FailureLines {
    private final Map<String, ConsoleLine> thrown = new ConcurrentHashMap<>();

    /**
     * @param line a console line; the first error of a robot that reads as a throw with its stack
     *     trace is kept (a controller's own {@code System.err} lines come one line at a time)
     */
    void seen(ConsoleLine line) {
        if (line.kind() == ConsoleLine.Kind.ERROR && line.text().contains("\n") && line.text().contains("threw ")) {
            thrown.putIfAbsent(line.source(), line);
        }
    }

    /** @param robot a robot's name @return the report of its controller's throw, or null */
    ConsoleLine of(String robot) {
        return thrown.get(robot);
    }
}
