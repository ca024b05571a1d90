package org.kheperasim.sim.host.loading;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * One definition of a stateless controller's classes for every robot of every run in the process
 * ({@link StatelessCheck}): the JIT then compiles them once and keeps what it learnt, where a class
 * defined anew for each robot is compiled anew, rarely past its first tier. A controller keeping state
 * in static fields keeps classes of its own for each robot, so each robot's statics stay its own.
 *
 * <p>A shared definition serves a load while the class files it was made from are unchanged (they
 * are read again and compared: a recompiled class is picked up), for the same classpath, name and
 * containment.
 */
public final class SharedControllers {
    private record Key(List<Path> classpath, String name, boolean contained) {
    }

    /** A shared definition: the class, and the class files of the controller's own classes it was made from. */
    private record Shared(Class<?> type, Map<String, byte[]> closure) {
    }

    private static final Map<Key, Shared> SHARED = new ConcurrentHashMap<>();

    private SharedControllers() {
    }

    /**
     * @param classpath the loader's classpath
     * @param name the controller's name as asked for
     * @param loader a fresh loader for that classpath (nothing defined in it yet)
     * @return the shared class for that name, when there is one and its class files are unchanged; else null
     */
    public static Class<?> lookUp(List<Path> classpath, String name, ControllerClassLoader loader) {
        Shared s = SHARED.get(new Key(List.copyOf(classpath), name, loader.contained()));
        if (s == null) {
            return null;
        }
        try {
            for (Map.Entry<String, byte[]> e : s.closure().entrySet()) {
                if (!Arrays.equals(e.getValue(), loader.ownClassFile(e.getKey()))) {
                    return null;
                }
            }
        } catch (ClassFormatError tooLarge) { // a class file grown past the limit: loading it anew says so
            return null;
        }
        return s.type();
    }

    /**
     * Offer a controller class just loaded (not yet initialised) for sharing: kept when its classes
     * keep no state of their own.
     *
     * @param classpath the loader's classpath
     * @param name the controller's name as asked for
     * @param type the class, defined by {@code loader}
     * @param loader its loader
     * @return true when it is shared from now on
     */
    public static boolean offer(List<Path> classpath, String name, Class<?> type, ControllerClassLoader loader) {
        StatelessCheck.Result r = StatelessCheck.check(type.getName().replace('.', '/'), loader::ownClassFile);
        if (!r.stateless() || r.closure().isEmpty()) {
            return false;
        }
        SHARED.put(new Key(List.copyOf(classpath), name, loader.contained()),
                new Shared(type, Map.copyOf(r.closure())));
        return true;
    }

    /**
     * Forget every shared definition: the next load of each controller defines its classes anew, as
     * in a fresh JVM. A graded run in a warm worker JVM starts so (grade.worker.WorkerLoop): each run
     * gets its own class loaders, as the run in a JVM of its own did.
     */
    public static void forget() {
        SHARED.clear();
    }

    /**
     * @param type a controller class
     * @return why it is not stateless (what {@link #offer} found), or null when it is; for messages and tests
     */
    public static String whyNotShared(Class<?> type) {
        if (!(type.getClassLoader() instanceof ControllerClassLoader loader)) {
            return "not loaded by a controller class loader";
        }
        return StatelessCheck.check(type.getName().replace('.', '/'), loader::ownClassFile).why();
    }
}
