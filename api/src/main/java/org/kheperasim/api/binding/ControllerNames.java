package org.kheperasim.api.binding;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.api.spi.ControllerException;

/**
 * How every backend names controllers, so that {@code --controller WallFollower} means the same
 * class in the simulator and on the robot: the name as given, then, for a name without a dot, the
 * bundled package. Loading the class is the backend's business (the simulator rewrites it onto the
 * simulation clock; robot-link loads it as it is).
 */
public final class ControllerNames {
    /** The package of the bundled controllers. */
    public static final String BUNDLED_PACKAGE = "org.kheperasim.controllers";
    /** The resource listing the bundled controllers' simple names, one a line ({@code #} comments). */
    public static final String INDEX = "org/kheperasim/controllers/bundled.txt";

    private ControllerNames() {
    }

    /**
     * @param loader the class loader that sees the bundled controllers
     * @return their simple names, in the index's order (empty when the controllers are not there)
     */
    public static List<String> bundled(ClassLoader loader) {
        List<String> names = new ArrayList<>();
        try (InputStream in = loader.getResourceAsStream(INDEX)) {
            if (in == null) {
                return names;
            }
            BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line; (line = r.readLine()) != null; ) {
                line = line.strip();
                if (!line.isEmpty() && !line.startsWith("#")) {
                    names.add(line);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return names;
    }

    /**
     * @param name what the user typed: a bundled controller's simple name, a default-package class
     *     name, or a fully qualified name
     * @return the class names to try, in order
     */
    public static List<String> candidates(String name) {
        List<String> candidates = new ArrayList<>();
        candidates.add(name);
        if (!name.contains(".")) {
            candidates.add(BUNDLED_PACKAGE + "." + name);
        }
        return candidates;
    }

    /**
     * Check a user's classpath entries exist.
     *
     * @param classpath folders and jars
     * @throws ControllerException naming the first entry that does not exist and the fix
     */
    public static void checkClasspath(List<Path> classpath) {
        for (Path p : classpath) {
            if (!Files.exists(p)) {
                throw new ControllerException("classpath entry " + p + " does not exist; give the folder your"
                        + " compiled .class files are in (e.g. the -d folder of javac) or a jar");
            }
        }
    }

    /**
     * Find a controller class by name: the first of {@link #candidates} that {@code loader} can
     * load, checked against the controller contract.
     *
     * @param name what the user typed
     * @param loader the class loader to look through (the backend's own kind)
     * @param bundled the bundled controllers' names, for the error
     * @param classpath the user's classpath, for the error
     * @param jar the program's jar, for the error's compile hint
     * @return the checked controller class
     * @throws ControllerException naming what was looked for and the fix
     */
    public static Class<?> resolve(String name, ClassLoader loader, List<String> bundled, List<Path> classpath,
            String jar) {
        for (String candidate : candidates(name)) {
            Class<?> type;
            try {
                type = Class.forName(candidate, false, loader);
            } catch (ClassNotFoundException | NoClassDefFoundError e) {
                continue;
            }
            Controllers.check(type);
            return type;
        }
        throw notFound(name, bundled, classpath, jar);
    }

    /**
     * The error for a name that matches no class.
     *
     * @param name what the user typed
     * @param bundled the bundled controllers' names
     * @param classpath the user's classpath
     * @param jar the program's jar, for the compile hint (e.g. {@code khepera-sim.jar})
     * @return the exception to throw, naming the controller, where it was looked for, and the fix
     */
    public static ControllerException notFound(String name, List<String> bundled, List<Path> classpath, String jar) {
        return new ControllerException("no controller named '" + name + "': it is not a bundled controller "
                + bundled + (classpath.isEmpty() ? " and no --classpath was given" : " and not on the classpath "
                + classpath) + ". Compile yours (javac -cp " + jar + " -d out Robot.java) and run with"
                + " --classpath out --controller Robot");
    }
}
