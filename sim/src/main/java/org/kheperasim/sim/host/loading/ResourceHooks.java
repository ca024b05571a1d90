package org.kheperasim.sim.host.loading;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.lang.StackWalker.Option;
import java.net.URL;
import java.util.Objects;

/**
 * What the controller class loader puts in place of the resource reads of contained controller code
 * ({@code Class.getResource}, {@code Class.getResourceAsStream}, {@code ClassLoader.getResource},
 * {@code ClassLoader.getResourceAsStream}; each hook takes the receiver first): a controller reads
 * the resources of its own classpath entry (a {@code config.properties} in its folder or jar), and
 * nothing else, whichever class or loader it asks. A class of the platform or the simulator, or the
 * loader of one (the context class loader, say), answers as the controller's own loader does: the
 * nearest controller class on the calling thread's stack decides which controller asks.
 */
public final class ResourceHooks {
    private static final StackWalker STACK = StackWalker.getInstance(Option.RETAIN_CLASS_REFERENCE);

    private ResourceHooks() {
    }

    /**
     * Replaces {@link Class#getResource(String)}.
     *
     * @return the resource of the controller's own classpath entry, or null
     */
    public static URL getResource(Class<?> type, String name) {
        ControllerClassLoader loader = loaderOf(type);
        return loader == null ? null : loader.findResource(resolve(type, name));
    }

    /**
     * Replaces {@link Class#getResourceAsStream(String)}.
     *
     * @return the resource's bytes (read once, so nothing stays open), or null
     */
    public static InputStream getResourceAsStream(Class<?> type, String name) {
        ControllerClassLoader loader = loaderOf(type);
        return loader == null ? null : stream(loader.ownResource(resolve(type, name)));
    }

    /**
     * Replaces {@link ClassLoader#getResource(String)}.
     *
     * @return the resource of the controller's own classpath entry, or null
     */
    public static URL getResource(ClassLoader loader, String name) {
        ControllerClassLoader own = loaderOf(loader);
        return own == null ? null : own.findResource(Objects.requireNonNull(name, "name"));
    }

    /** Replaces {@link ClassLoader#getResourceAsStream(String)}. */
    public static InputStream getResourceAsStream(ClassLoader loader, String name) {
        ControllerClassLoader own = loaderOf(loader);
        return own == null ? null : stream(own.ownResource(Objects.requireNonNull(name, "name")));
    }

    private static ControllerClassLoader loaderOf(Class<?> type) {
        return type.getClassLoader() instanceof ControllerClassLoader own ? own : callersLoader();
    }

    private static ControllerClassLoader loaderOf(ClassLoader loader) {
        Objects.requireNonNull(loader, "loader"); // as calling the method on null would
        return loader instanceof ControllerClassLoader own ? own : callersLoader();
    }

    /** The loader of the nearest controller class on the stack, or null when no controller code asks. */
    private static ControllerClassLoader callersLoader() {
        return STACK.walk(frames -> frames.map(f -> f.getDeclaringClass().getClassLoader())
                .filter(ControllerClassLoader.class::isInstance).map(ControllerClassLoader.class::cast)
                .findFirst().orElse(null));
    }

    /** A name relative to the class's package, as {@link Class#getResource(String)} resolves it. */
    private static String resolve(Class<?> type, String name) {
        Objects.requireNonNull(name, "name");
        if (name.startsWith("/")) {
            return name.substring(1);
        }
        Class<?> c = type;
        while (c.isArray()) {
            c = c.getComponentType();
        }
        String pkg = c.getPackageName();
        return pkg.isEmpty() ? name : pkg.replace('.', '/') + "/" + name;
    }

    private static InputStream stream(byte[] bytes) {
        return bytes == null ? null : new ByteArrayInputStream(bytes);
    }
}
