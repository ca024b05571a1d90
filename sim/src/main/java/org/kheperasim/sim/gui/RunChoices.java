package org.kheperasim.sim.gui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.engine.model.Settings;

/**
 * What the next run uses, as the window's menus set it: the arena's file, settings, seed,
 * controller (and where it comes from), containment, speed. Event thread only.
 */
final class RunChoices {
    /** The arena's file, or null for a bundled or new arena. */
    Path arenaFile;
    Settings settings = Settings.defaults();
    /** The next run's seed, or null for a new random one each run. */
    Long seed;
    String controllerName;
    List<Path> classpath = new ArrayList<>();
    /** The .java the controller was compiled from, or null. */
    Path javaSource;
    /** The class {@link #javaSource} defines (with its package), or null. */
    String sourceClass;
    /** The text of {@link #javaSource} the loaded classes were compiled from, or null when none compiled. */
    String compiledText;
    /** The text of {@link #javaSource} whose compilation failed last, or null when the last one compiled. */
    String failedText;
    /** The compiler's first error for {@link #failedText}, e.g. {@code MyFirst.java:16:28: error: ';' expected}. */
    String failedError;
    /** Run the controller uncontained (Controller > Trust this controller); off by default. */
    boolean trusted;
    /** Simulated seconds per real second. */
    double speed = 1;
}
