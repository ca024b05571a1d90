package org.kheperasim.sim.host.loading;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URL;
import java.nio.file.Path;
import java.security.ProtectionDomain;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Enumeration;
import java.util.List;
import java.util.Objects;
import org.kheperasim.sim.host.ContainingLoader;

/**
 * Loads controller classes with their time calls rewritten onto the simulation clock (see
 * {@link TimeCallRewriter}).
 *
 * <p>Classes of the Java platform, of the simulator ({@code org.kheperasim.api}, {@code .sim} and
 * {@code .link}) and of the simulator's libraries always come from the parent, so the controller
 * and the simulator share the API types and the {@link org.kheperasim.sim.host.SimClock} hooks.
 * Every other class is looked up child-first: in the classpath entries in order, then as a class
 * file resource of the parent (that is how the controllers bundled with the simulator get
 * rewritten too), and defined here after rewriting; a class found nowhere is left to the parent.
 * Each loader defines its own classes, so a new loader picks up a recompiled controller.
 *
 * <p>A loader that contains its code ({@link #contained()}, the default) checks every class against
 * the controller allowlist before it defines it, together with every class of the controller's own
 * that class can reach ({@link ControllerCheck}); the code's resource reads then see its classpath
 * entries only ({@link ResourceHooks}), never the simulator's jar or classpath. Resources are
 * looked up in the classpath entries first, then in the parent. Closing the loader closes its jar
 * files; classes and resources not yet loaded from them can then no longer be found.
 */
public final class ControllerClassLoader extends ClassLoader implements Closeable, ContainingLoader {
    static {
        registerAsParallelCapable();
    }

    /** Names starting with these always come from the parent. */
    private static final List<String> SHARED_PREFIXES = List.of(
            "java.", "javax.", "jdk.", "sun.", "com.sun.",
            "org.objectweb.asm.", "picocli.", "org.junit.", "org.opentest4j.", "org.apiguardian.");

    /**
     * The simulator's own packages: a name in one of them is the simulator's when the simulator
     * defines it, and otherwise a class of the controller's classpath (a course's own class placed in
     * {@code edu.wsu.KheperaSimulator} to reach the API, as a fork of the WSU simulator did). Defined
     * by this loader, such a class is in another runtime package than the simulator's classes of the
     * same package name, so it gets no package-private access to them (the JVM throws
     * {@link IllegalAccessError}).
     */
    private static final List<String> SIMULATOR_PREFIXES = List.of(
            "org.kheperasim.api.", "org.kheperasim.sim.", "org.kheperasim.link.", "edu.wsu.KheperaSimulator.");

    /** Names in the simulator's packages that the simulator does not define, by name: decided once per loader. */
    private final java.util.Map<String, Boolean> simulatorDefines = new java.util.concurrent.ConcurrentHashMap<>();
    /** Names the simulator defines that a classpath entry holds too (the simulator's are used), in order. */
    private final java.util.Set<String> shadowed =
            java.util.Collections.synchronizedSet(new java.util.LinkedHashSet<>());

    private final List<ClasspathEntry> roots;
    private final ClassHierarchy hierarchy;
    private final boolean contained;
    private final ControllerCheck check;
    /** Its code's own monitors for objects it does not own (see {@link MonitorHooks}). */
    private final Monitors monitors = new Monitors(this);
    /** Class files read for the check and the hierarchy, by internal name (empty: none). */
    private final java.util.Map<String, java.util.Optional<byte[]>> classFiles =
            new java.util.concurrent.ConcurrentHashMap<>();
    /** Where each class file read came from, by internal name, for messages. */
    private final java.util.Map<String, String> locations = new java.util.concurrent.ConcurrentHashMap<>();

    /**
     * @param classpath directories and jar files of the user's compiled classes, searched in order
     *     as with {@code java -cp}; may be empty
     * @param parent the simulator's class loader: it must see the API and the simulator
     * @throws IllegalArgumentException when a classpath entry is neither a directory nor a file
     * @throws UncheckedIOException when a jar file cannot be opened
     */
    public ControllerClassLoader(List<Path> classpath, ClassLoader parent) {
        this(classpath, parent, true);
    }

    /**
     * @param classpath see {@link #ControllerClassLoader(List, ClassLoader)}
     * @param parent see {@link #ControllerClassLoader(List, ClassLoader)}
     * @param contained true (the default) to contain the code: a class that uses anything the
     *     controller allowlist does not allow is refused ({@link ControllerPolicyError}), and the
     *     calls that could end the application, stall a run or leave it go to the simulator's hooks
     *     ({@link org.kheperasim.sim.host.Containment} and the others); false only for a controller
     *     the user trusts
     */
    public ControllerClassLoader(List<Path> classpath, ClassLoader parent, boolean contained) {
        super(Objects.requireNonNull(parent, "parent"));
        this.contained = contained;
        this.roots = open(classpath);
        this.hierarchy = new ClassHierarchy(this::localClassFile, parent);
        this.check = new ControllerCheck(new ControllerPolicy(Allowlist.bundled(), hierarchy), this::localClassFile,
                n -> locations.getOrDefault(n, n + ".class"), !contained);
    }

    /** @return the stand-ins its code locks for objects it does not own */
    Monitors monitors() {
        return monitors;
    }

    /** @return true when it contains the code it loads (rewrites its escapes and thread calls) */
    @Override
    public boolean contained() {
        return contained;
    }

    private static List<ClasspathEntry> open(List<Path> classpath) {
        List<ClasspathEntry> opened = new ArrayList<>();
        try {
            for (Path entry : classpath) {
                opened.add(ClasspathEntry.open(entry));
            }
            return List.copyOf(opened);
        } catch (RuntimeException e) {
            for (ClasspathEntry root : opened) {
                try {
                    root.close();
                } catch (IOException suppressed) {
                    e.addSuppressed(suppressed);
                }
            }
            throw e;
        }
    }

    /**
     * @return whether {@code className} comes from the parent: a platform or library name, or one the simulator defines
     */
    private boolean isShared(String className) {
        for (String prefix : SHARED_PREFIXES) {
            if (className.startsWith(prefix)) {
                return true;
            }
        }
        for (String prefix : SIMULATOR_PREFIXES) {
            if (className.startsWith(prefix)) {
                return simulatorDefines.computeIfAbsent(className, this::parentDefines);
            }
        }
        return false;
    }

    /** @return whether the simulator (the parent) has a class file for the name; notes a copy on the classpath */
    private boolean parentDefines(String className) {
        String resource = className.replace('.', '/') + ".class";
        if (getParent().getResource(resource) == null) {
            return false;
        }
        for (ClasspathEntry root : roots) {
            if (root.url(resource) != null) {
                shadowed.add(className);
                break;
            }
        }
        return true;
    }

    /**
     * @return the names in the simulator's packages that both the simulator and the classpath define,
     *     as far as they were asked for: the simulator's own class is used, the classpath's ignored
     */
    public List<String> shadowed() {
        synchronized (shadowed) {
            return List.copyOf(shadowed);
        }
    }

    /**
     * @return whether the name is in one of the simulator's packages (then only the classpath entries hold its class
     *     file)
     */
    private static boolean inSimulatorPackage(String className) {
        for (String prefix : SIMULATOR_PREFIXES) {
            if (className.startsWith(prefix)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Load a class: shared names from the parent, every other name child-first (see the class
     * comment).
     *
     * @throws ClassNotFoundException when the class is found nowhere, or its class file cannot be
     *     read (the message names the file)
     * @throws ClassFormatError when its class file is malformed or too new (the message names the
     *     class and the file)
     * @throws NoClassDefFoundError when its class file holds a class of another name, or its
     *     superclass is missing (the message names the file)
     */
    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        if (isShared(name)) {
            return getParent().loadClass(name);
        }
        synchronized (getClassLoadingLock(name)) {
            Class<?> type = findLoadedClass(name);
            if (type == null) {
                type = defineLocal(name);
            }
            if (type == null) {
                type = getParent().loadClass(name);
            }
            if (resolve) {
                resolveClass(type);
            }
            return type;
        }
    }

    /**
     * Find, rewrite and define a class; null when no class file for it exists.
     *
     * @throws ClassFormatError (or {@link UnsupportedClassVersionError}) when its class file, or
     *     that of a class of its own it reaches, is too large, malformed or too new: the one-line
     *     message begins with that file and ends with the fix
     */
    private Class<?> defineLocal(String name) throws ClassNotFoundException {
        ClassFile found;
        try {
            found = findClassFile(name);
        } catch (ClasspathEntry.TooLarge e) {
            throw withCause(new ClassFormatError(e.getMessage()), e);
        } catch (IOException e) {
            throw new ClassNotFoundException("Cannot read class " + name + ": " + e.getMessage(), e);
        }
        if (found == null) {
            return null;
        }
        String failure = "Cannot load class " + name + " from " + found.location() + ": ";
        byte[] bytes = found.bytes();
        try {
            // The check reads class files through the same cache: what is defined is what was checked,
            // even if the file changes on disk meanwhile. For trusted code it only reads them: a class
            // file too new or malformed that the controller reaches is refused before its run, in one
            // line, not when its code first runs into it.
            String internalName = name.replace('.', '/');
            locations.putIfAbsent(internalName, found.location());
            bytes = classFiles.compute(internalName, (n, read) -> read != null && read.isPresent() ? read
                    : java.util.Optional.of(found.bytes())).get();
            check.checkReachable(internalName); // a bad class file's error names its file already
        } catch (ControllerPolicyError e) {
            throw withCause(new ControllerPolicyError(failure + e.getMessage()), e);
        }
        byte[] rewritten;
        try {
            rewritten = TimeCallRewriter.rewrite(bytes, hierarchy, contained);
        } catch (UnsupportedClassVersionError e) {
            throw withCause(new UnsupportedClassVersionError(found.location() + ": " + e.getMessage()), e);
        } catch (ClassFormatError e) {
            throw withCause(new ClassFormatError(found.location() + ": " + e.getMessage()), e);
        }
        try {
            return defineClass(name, rewritten, 0, rewritten.length, found.domain());
        } catch (UnsupportedClassVersionError e) {
            throw withCause(new UnsupportedClassVersionError(failure + e.getMessage()), e);
        } catch (ClassFormatError e) {
            throw withCause(new ClassFormatError(failure + e.getMessage()), e);
        } catch (NoClassDefFoundError e) { // a file in the wrong directory, or a missing superclass
            throw withCause(new NoClassDefFoundError(failure + e.getMessage()), e);
        }
    }

    /** A class file and where it was found. */
    private record ClassFile(byte[] bytes, String location, ProtectionDomain domain) {
    }

    /** The class file this loader would define for {@code className}, or null. */
    private ClassFile findClassFile(String className) throws IOException {
        String resource = className.replace('.', '/') + ".class";
        for (ClasspathEntry root : roots) {
            byte[] bytes = root.read(resource);
            if (bytes != null) {
                return new ClassFile(bytes, root.describe(resource), root.domain);
            }
        }
        if (inSimulatorPackage(className)) {
            return null; // not the simulator's (isShared), nor on the classpath
        }
        URL url = getParent().getResource(resource);
        if (url == null) {
            return null;
        }
        try (InputStream in = url.openStream()) {
            return new ClassFile(ClasspathEntry.readBounded(in, url.toString()), url.toString(), null);
        } catch (IOException e) {
            throw new IOException("cannot read " + url + ": " + e.getMessage(), e);
        }
    }

    /**
     * @param internalName a class's internal name
     * @return the class file this loader defines (or would define) for it, as read from its classpath or the
     *     simulator's controllers, before rewriting; null for a class it leaves to its parent
     */
    byte[] ownClassFile(String internalName) {
        return localClassFile(internalName);
    }

    /** For {@link ClassHierarchy}: the class file of a class this loader defines itself, or null. */
    private byte[] localClassFile(String internalName) {
        String className = internalName.replace('/', '.');
        if (isShared(className)) {
            return null;
        }
        // The check and the hierarchy ask for the same class files many times: read each once.
        return classFiles.computeIfAbsent(internalName, n -> {
            try {
                ClassFile found = findClassFile(className);
                if (found != null) {
                    locations.putIfAbsent(n, found.location());
                }
                return java.util.Optional.ofNullable(found == null ? null : found.bytes());
            } catch (ClasspathEntry.TooLarge e) {
                throw withCause(new ClassFormatError(e.getMessage()), e); // refused, never read
            } catch (IOException e) {
                return java.util.Optional.empty(); // then the parent is asked; loading the class reports the failure
            }
        }).orElse(null);
    }

    /**
     * Check a class, and every class of the controller's own it reaches, against the allowlist,
     * without defining any (what loading it does first, when the loader contains its code).
     *
     * @param className the class's binary name
     * @throws ControllerPolicyError naming the first use refused
     */
    void check(String className) {
        check.checkReachable(className.replace('.', '/'));
    }

    /**
     * Look a resource up in the classpath entries first, then in the parent: for the simulator's own
     * code (its service lookups of controller styles, say). Contained controller code never reaches
     * this method: its resource reads are rewritten to {@link ResourceHooks}, which read only the
     * classpath entries ({@link #findResource} and {@link #ownResource}).
     *
     * @return the resource, or null
     */
    @Override
    public URL getResource(String name) {
        URL url = findResource(name);
        return url != null ? url : getParent().getResource(name);
    }

    /**
     * All copies of a resource: those in the classpath entries in order, then the parent's (see {@link #getResource}).
     */
    @Override
    public Enumeration<URL> getResources(String name) throws IOException {
        List<URL> urls = Collections.list(findResources(name));
        urls.addAll(Collections.list(getParent().getResources(name)));
        return Collections.enumeration(urls);
    }

    /**
     * @param name a resource name, relative to the classpath entries' roots
     * @return its bytes from the first classpath entry that has it, or null (also when it cannot be read)
     */
    byte[] ownResource(String name) {
        for (ClasspathEntry root : roots) {
            try {
                byte[] bytes = root.read(name);
                if (bytes != null) {
                    return bytes;
                }
            } catch (IOException e) {
                return null; // as ClassLoader.getResourceAsStream answers an unreadable resource
            }
        }
        return null;
    }

    /** @return the resource in the first classpath entry that has it, or null */
    @Override
    protected URL findResource(String name) {
        for (ClasspathEntry root : roots) {
            URL url = root.url(name);
            if (url != null) {
                return url;
            }
        }
        return null;
    }

    /** @return the resource in every classpath entry that has it, in classpath order */
    @Override
    protected Enumeration<URL> findResources(String name) {
        List<URL> urls = new ArrayList<>();
        for (ClasspathEntry root : roots) {
            URL url = root.url(name);
            if (url != null) {
                urls.add(url);
            }
        }
        return Collections.enumeration(urls);
    }

    /** Close the jar files of the classpath. */
    @Override
    public void close() throws IOException {
        IOException failure = null;
        for (ClasspathEntry root : roots) {
            try {
                root.close();
            } catch (IOException e) {
                if (failure == null) {
                    failure = e;
                } else {
                    failure.addSuppressed(e);
                }
            }
        }
        if (failure != null) {
            throw failure;
        }
    }

    private static <T extends Throwable> T withCause(T error, Throwable cause) {
        error.initCause(cause);
        return error;
    }
}
