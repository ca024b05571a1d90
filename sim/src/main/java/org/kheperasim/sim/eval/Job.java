package org.kheperasim.sim.eval;

import java.nio.file.Path;
import java.util.Map;
import java.util.Objects;
import org.kheperasim.api.Parameters;
import org.kheperasim.link.tool.CliNumbers;

/**
 * One run to evaluate: a controller with its parameters, in an arena, with a seed, for a simulated
 * time; deterministic like every run, so the same job gives the same outcome on any thread, in any
 * order, on any machine.
 *
 * @param index the job's place in its batch (its input line, from 0): outcomes are joined in this order
 * @param id a name the caller gives it, echoed in its outcome (may be empty)
 * @param controller a bundled controller or a class on the evaluator's classpath
 * @param arena a bundled arena's name or an arena (or WSU world) file
 * @param seed the run's seed
 * @param seconds simulated seconds, &gt; 0 and at most {@link #MAX_SECONDS}
 * @param parameters what the controller reads with {@code parameters()}
 * @param settings settings other than the defaults ({@code key -> value}, as {@code --set} takes them)
 * @param trace where to write the run's trace, or null for none
 */
public record Job(long index, String id, String controller, String arena, long seed, double seconds,
        Parameters parameters,
        Map<String, String> settings, Path trace) {
    /** The longest simulated time of a job, s: the command line's own limit ({@code run --seconds}). */
    public static final double MAX_SECONDS = CliNumbers.MAX_SECONDS;

    /** Checks the parts. */
    public Job {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(controller, "controller");
        Objects.requireNonNull(arena, "arena");
        Objects.requireNonNull(parameters, "parameters");
        settings = Map.copyOf(settings);
        if (!(seconds > 0) || !(seconds <= MAX_SECONDS)) {
            throw new IllegalArgumentException("seconds " + seconds
                    + ": give a simulated time greater than 0 and at most "
                    + (long) MAX_SECONDS + " (about 3 years)");
        }
    }
}
