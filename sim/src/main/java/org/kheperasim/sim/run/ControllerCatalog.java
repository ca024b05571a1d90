package org.kheperasim.sim.run;

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
import org.kheperasim.api.spi.Controllers;
import org.kheperasim.sim.host.loading.ControllerClassLoader;

/**
 * Finds controller classes by name: a bundled controller ({@code WallFollower}), or a class the
 * user compiled, found on a classpath of folders and jars (as with {@code java -cp}). Every class
 * comes through a fresh {@link ControllerClassLoader}, which puts it on the simulation clock and
 * picks up a recompiled class.
 */
public final class ControllerCatalog {
    /** The package of the bundled controllers. */
    public static final String BUNDLED_PACKAGE = "org.kheperasim.controllers";
    private static final String INDEX = "org/kheperasim/controllers/bundled.txt";

    private final List<Path> classpath;

    /** @param classpath folders and jars with the user's compiled classes (may be empty) */
    public ControllerCatalog(List<Path> classpath) {
        for (Path p : classpath) {
            if (!Files.exists(p)) {
                throw new ControllerException("classpath entry " + p + " does not exist; give the folder your"
                        + " compiled .class files are in (e.g. the -d folder of javac) or a jar");
            }
        }
        this.classpath = List.copyOf(classpath);
    }

    /** @return the simple names of the bundled controllers */
    public static List<String> bundled() {
        List<String> names = new ArrayList<>();
        try (InputStream in = ControllerCatalog.class.getClassLoader().getResourceAsStream(INDEX)) {
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
     * Load a controller class through a new controller class loader.
     *
     * @param name a bundled controller's simple name, or a class name (simple for the default
     *     package, or fully qualified) on the classpath
     * @return the checked controller class
     * @throws ControllerException naming what was looked for and how to fix it
     */
    public Class<?> load(String name) {
        ControllerClassLoader loader = new ControllerClassLoader(classpath, ControllerCatalog.class.getClassLoader());
        List<String> candidates = new ArrayList<>();
        candidates.add(name);
        if (!name.contains(".")) {
            candidates.add(BUNDLED_PACKAGE + "." + name);
        }
        for (String candidate : candidates) {
            Class<?> type;
            try {
                type = Class.forName(candidate, false, loader);
            } catch (ClassNotFoundException | NoClassDefFoundError e) {
                continue;
            }
            Controllers.check(type);
            return type;
        }
        throw new ControllerException("no controller named '" + name + "': it is not a bundled controller "
                + bundled() + (classpath.isEmpty() ? " and no --classpath was given" : " and not on the classpath "
                + classpath) + ". Compile yours (javac -cp khepera-sim.jar -d out Robot.java) and run with"
                + " --classpath out --controller Robot");
    }
}
