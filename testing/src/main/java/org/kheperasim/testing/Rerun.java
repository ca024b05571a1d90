package org.kheperasim.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * A run made again and compared with the first, trace against trace: what {@code khepera-sim verify}
 * says. Made by {@link Run#rerun()}.
 */
public final class Rerun {
    private final Run again;
    private final List<String> header;
    private final Optional<String> firstDifference;
    private final int samples;

    Rerun(Run again, List<String> header, Optional<String> firstDifference, int samples) {
        this.again = again;
        this.header = List.copyOf(header);
        this.firstDifference = firstDifference;
        this.samples = samples;
    }

    /** @return true when the run made again has the same trace, line for line */
    public boolean identical() {
        return header.isEmpty() && firstDifference.isEmpty();
    }

    /**
     * @return the first sample line that differs, in words, e.g. {@code sample line 1234 (t = 61.700 s,
     *     robot 0): x_mm recorded 100.000, now 100.100}; empty when every sample agrees
     */
    public Optional<String> firstDifference() {
        return firstDifference;
    }

    /**
     * @return one line per header field that differs (seed, arena, controller, settings), e.g.
     *     {@code settings: recorded 'defaults', now '...'}
     */
    public List<String> headerDifferences() {
        return header;
    }

    /** @return the sample lines the first run's trace has */
    public int samples() {
        return samples;
    }

    /** @return the run made again */
    public Run again() {
        return again;
    }

    /** @return {@code identical: N sample lines}, or what differs */
    @Override
    public String toString() {
        if (identical()) {
            return "identical: " + samples + " sample lines";
        }
        List<String> parts = new ArrayList<>(header);
        firstDifference.ifPresent(d -> parts.add("first difference at " + d));
        return "differs: " + String.join("; ", parts);
    }

    /** A recorded run's spec with its controllers looked up on the test's classpath. */
    static RunSpec withClasspath(RunSpec recorded) {
        Set<Path> classpath = new LinkedHashSet<>();
        List<String> names = new ArrayList<>();
        for (String c : recorded.controllers()) {
            ControllerClasses.Found found;
            try {
                found = ControllerClasses.named(c);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("the recorded run's controller " + c
                        + " is not on the test's classpath,"
                        + " so it cannot be run again; put the class (the same version) in the test project", e);
            }
            names.add(found.name());
            found.root().ifPresent(classpath::add);
        }
        return new RunSpec(recorded.arenaArg(), recorded.arena(), names, recorded.settings(),
                new ArrayList<>(classpath),
                recorded.seed(), recorded.seconds(), recorded.sampleMillis(), recorded.trusted(),
                recorded.hangTimeoutSeconds(), recorded.edits());
    }
}
