package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.kheperasim.sim.testkit.KitConsoleLine;

/**
 * What a live run's console tells a test: the controllers' messages and the simulator's errors, each error
 * with the student's line where it can be found.
 */
final class RunCapture implements Consumer<KitConsoleLine> {

    /**
     * An error the simulator reported about a controller.
     *
     * @param source the robot's controller name, as the console shows it ({@code Name} or {@code Name#1})
     * @param nanos simulated time, ns
     * @param text what it said
     * @param where the student's line, when found
     */
    record Error(String source, long nanos, String text, Optional<String> where) {
    }

    private final List<String> console = new ArrayList<>();
    private final List<Error> errors = new ArrayList<>();

    @Override
    public synchronized void accept(KitConsoleLine line) {
        console.add(line.formatted());
        if (line.error()) {
            // A rule broken at run time is refused on the controller's own thread: its stack names the line.
            Optional<String> where = StudentLines.inText(line.text())
                    .or(() -> StudentLines.belowRefusal(Thread.currentThread().getStackTrace()));
            errors.add(new Error(line.source(), line.timeNanos(), line.text(), where));
        }
    }

    /** @return the console's lines, as {@code khepera-sim run} prints them */
    synchronized List<String> console() {
        return List.copyOf(console);
    }

    /**
     * @param source a robot's controller name as the console shows it
     * @return the first error reported for it, or empty
     */
    synchronized Optional<Error> firstError(String source) {
        return errors.stream().filter(e -> e.source().equals(source)).findFirst();
    }
}
