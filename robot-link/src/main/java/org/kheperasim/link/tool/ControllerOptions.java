package org.kheperasim.link.tool;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Option;

/**
 * The options that choose and time a controller, the same on both tools: {@code khepera-sim run}
 * and {@code khepera-link run}. A picocli mixin.
 */
public final class ControllerOptions {

    @Option(names = "--controller", required = true, paramLabel = "NAME",
            completionCandidates = BundledControllers.class,
            description = "a bundled controller (${COMPLETION-CANDIDATES}) or a class name on --classpath")
    String controller;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controller classes, as with java -cp")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--seconds", paramLabel = "T", converter = CliNumbers.PositiveSeconds.class,
            description = "how long to run, seconds > 0: simulated time in khepera-sim (default 600),"
                    + " real time on the robot (default: until the controller ends or Ctrl-C)")
    Double seconds;

    /** @return the controller's name as given */
    public String controller() {
        return controller;
    }

    /** @return the user's classpath entries (may be empty) */
    public List<Path> classpath() {
        return List.copyOf(classpath);
    }

    /**
     * @param dflt what to use when {@code --seconds} was not given
     * @return how long to run, seconds
     */
    public double seconds(double dflt) {
        return seconds == null ? dflt : seconds;
    }

    /** @return whether {@code --seconds} was given */
    public boolean hasSeconds() {
        return seconds != null;
    }
}
