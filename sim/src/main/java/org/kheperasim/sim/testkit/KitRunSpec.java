package org.kheperasim.sim.testkit;

import java.nio.file.Path;
import java.util.List;

/**
 * What to run, as {@code khepera-sim run}'s options say it.
 *
 * @param arena the arena
 * @param controllers each robot's controller (a bundled controller's simple name or a class name)
 * @param settings each robot's settings
 * @param classpath the folders and jars the controllers come from (empty for bundled ones)
 * @param seed the seed
 * @param seconds simulated seconds to run
 * @param sampleMillis the trace's sample period, whole ms
 * @param trusted true to run the controllers uncontained ({@code --trusted})
 * @param hangTimeoutSeconds real seconds without an API call after which a controller counts as hung
 * @param edits a window's arena edits to replay, or null
 */
public record KitRunSpec(KitArena arena, List<String> controllers, List<KitSettings> settings, List<Path> classpath,
        long seed, double seconds, long sampleMillis, boolean trusted, double hangTimeoutSeconds, KitEdits edits) {
    /** Copies the lists. */
    public KitRunSpec {
        controllers = List.copyOf(controllers);
        settings = List.copyOf(settings);
        classpath = List.copyOf(classpath);
    }
}
