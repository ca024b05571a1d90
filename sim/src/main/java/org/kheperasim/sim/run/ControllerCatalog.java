package org.kheperasim.sim.run;

import java.nio.file.Path;
import java.util.List;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.binding.ControllerNames;
import org.kheperasim.sim.host.loading.ControllerClassLoader;
import org.kheperasim.sim.host.loading.ControllerPolicyError;
import org.kheperasim.sim.host.loading.SharedControllers;

/**
 * Finds controller classes by name: a bundled controller ({@code WallFollower}), or a class the
 * user compiled, found on a classpath of folders and jars (as with {@code java -cp}). Every class
 * comes through a fresh {@link ControllerClassLoader}, which puts it on the simulation clock and
 * picks up a recompiled class. The naming rules are {@link ControllerNames}', shared with robot-link.
 */
public final class ControllerCatalog {
    /** The package of the bundled controllers. */
    public static final String BUNDLED_PACKAGE = ControllerNames.BUNDLED_PACKAGE;

    private final List<Path> classpath;
    private final boolean trusted;
    /**
     * The bundled controllers' names, read from the jar once per process: every run makes a catalog, and
     * reading the index each time (a jar entry inflated under the jar's lock) was a point where an
     * evaluation's threads waited on each other.
     */
    private static final List<String> BUNDLED =
            List.copyOf(ControllerNames.bundled(ControllerCatalog.class.getClassLoader()));
    /** The shared (stateless) controllers this catalog has served, by name: checked once per catalog (a run's). */
    private final java.util.Map<String, Class<?>> loaded = new java.util.concurrent.ConcurrentHashMap<>();

    /** @param classpath folders and jars with the user's compiled classes (may be empty) */
    public ControllerCatalog(List<Path> classpath) {
        this(classpath, false);
    }

    /**
     * @param classpath folders and jars with the user's compiled classes (may be empty)
     * @param trusted true to load them uncontained: calls to files, the network, reflection and so on
     *     are allowed and {@code System.exit} is not caught (only for a controller the user trusts;
     *     see docs/controller-rules.md)
     */
    public ControllerCatalog(List<Path> classpath, boolean trusted) {
        ControllerNames.checkClasspath(classpath);
        for (Path p : classpath) {
            String bad = ControllerHints.badEntry(p);
            if (bad != null) {
                throw new ControllerException(bad);
            }
        }
        this.classpath = List.copyOf(classpath);
        this.trusted = trusted;
    }

    /** @return the simple names of the bundled controllers */
    public static List<String> bundled() {
        return BUNDLED;
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
        Class<?> known = loaded.get(name);
        if (known != null) {
            return known;
        }
        ControllerClassLoader loader =
                new ControllerClassLoader(classpath, ControllerCatalog.class.getClassLoader(), !trusted);
        // A stateless controller's classes are defined once in the process (the JIT compiles them once).
        Class<?> shared = SharedControllers.lookUp(classpath, name, loader);
        if (shared != null) {
            loaded.put(name, shared);
            return shared;
        }
        try {
            if (!anyLoads(name, loader)) {
                // A wrong name: say what was most likely meant and what to type, or else where it was looked for.
                String hint = ControllerHints.hint(name, BUNDLED, classpath);
                throw hint != null ? new ControllerException("no controller named '" + name + "': " + hint)
                        : ControllerNames.notFound(name, BUNDLED, classpath, "khepera-sim.jar");
            }
            Class<?> type;
            try {
                type = ControllerNames.resolve(name, loader, BUNDLED, classpath, "khepera-sim.jar");
            } catch (ControllerException | LinkageError e) {
                String both = bothDefine(loader);
                if (both == null || e instanceof ControllerPolicyError) {
                    throw e;
                }
                throw new ControllerException("controller " + name + " cannot be loaded: " + e.getMessage()
                        + "; " + both, e);
            }
            if (SharedControllers.offer(classpath, name, type, loader)) {
                loaded.put(name, type);
            }
            return type;
        } catch (ControllerPolicyError e) {
            throw new ControllerException("controller " + name + " was refused: " + e.getMessage(), e);
        } catch (ClassFormatError e) { // a class file too large, malformed or too new: the message names it and the fix
            throw new ControllerException("controller " + name + " cannot be loaded: " + e.getMessage(), e);
        }
    }

    /**
     * @return what to say of the names in the simulator's packages that the classpath defines too
     *     (a course's copy of the original simulator's classes), or null when there are none
     */
    private static String bothDefine(ControllerClassLoader loader) {
        List<String> both = loader.shadowed();
        if (both.isEmpty()) {
            return null;
        }
        return both.get(0) + (both.size() > 1 ? " (and " + (both.size() - 1) + " more)" : "")
                + " is defined by both the"
                + " simulator and the classpath: the simulator's own class is used, the classpath's ignored;"
                + " remove it from the classpath, or name your class otherwise";
    }

    /** @return true when some class the name may mean can be found (loaded, not initialised) */
    private static boolean anyLoads(String name, ClassLoader loader) {
        for (String candidate : ControllerNames.candidates(name)) {
            try {
                Class.forName(candidate, false, loader);
                return true;
            } catch (ClassNotFoundException | NoClassDefFoundError | IllegalArgumentException e) {
                // Not this one; ControllerNames.resolve tries the same candidates and names them all.
                continue;
            }
        }
        return false;
    }
}
