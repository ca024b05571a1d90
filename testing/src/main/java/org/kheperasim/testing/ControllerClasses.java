package org.kheperasim.testing;

import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.Optional;
import org.kheperasim.sim.testkit.TestKit;

/**
 * Where a test's controller class comes from, in the terms of {@code khepera-sim run}: the name to give
 * {@code --controller} and the folder or jar to give {@code --classpath} (none for a bundled controller).
 * The simulator then loads the class itself, through its own class loader, rewritten onto the simulated
 * clock and contained, as it loads any student's class: never the copy the test's class loader holds.
 */
final class ControllerClasses {

    /**
     * @param name the name for {@code --controller}
     * @param root the folder or jar for {@code --classpath}, or empty for a bundled controller
     */
    record Found(String name, Optional<Path> root) {
    }

    private ControllerClasses() {
    }

    /**
     * @param type a controller class on the test's classpath
     * @return its name and where it was loaded from
     */
    static Found of(Class<?> type) {
        if (type.getPackageName().equals(TestKit.bundledControllerPackage())) {
            return new Found(type.getSimpleName(), Optional.empty());
        }
        CodeSource source = type.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            throw new IllegalArgumentException("cannot tell where the class " + type.getName()
                    + " was loaded from (no code"
                    + " source); give a class compiled into a folder or jar on the test's classpath");
        }
        return new Found(type.getName(), Optional.of(path(source.getLocation(), type.getName())));
    }

    /**
     * @param name a bundled controller's name, or a class name (fully qualified, or simple in the default package)
     * @return its name and where its class file lies on the test's classpath
     * @throws IllegalArgumentException naming the controller and the fix when there is no such class
     */
    static Found named(String name) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException(
                    "no controller named: give a controller class name, e.g. Run.of(\"MyController\"),"
                    + " or its class, Run.of(MyController.class)");
        }
        if (!name.contains(".") && TestKit.bundledControllers().contains(name)
                || name.startsWith(TestKit.bundledControllerPackage() + ".")) {
            return new Found(name, Optional.empty());
        }
        String resource = name.replace('.', '/') + ".class";
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        URL url = (loader != null ? loader : ControllerClasses.class.getClassLoader()).getResource(resource);
        if (url == null) {
            throw new IllegalArgumentException("no controller class '" + name
                    + "' on the test's classpath, and no bundled"
                    + " controller of that name (bundled: " + String.join(", ", TestKit.bundledControllers())
                    + "); give the"
                    + " class's full name with its package, e.g. Run.of(\"mypackage." + name + "\"), or its class:"
                    + " Run.of(" + name.substring(name.lastIndexOf('.') + 1) + ".class)");
        }
        return new Found(name, Optional.of(rootOf(url, resource, name)));
    }

    /** The classpath entry a class file's URL lies in: the jar, or the folder its package starts in. */
    private static Path rootOf(URL url, String resource, String name) {
        if (url.getProtocol().equals("jar")) {
            String spec = url.getPath();
            try {
                return Path.of(new java.net.URI(spec.substring(0, spec.indexOf("!/"))));
            } catch (URISyntaxException | RuntimeException e) {
                throw new IllegalArgumentException("cannot tell which jar the class " + name + " comes from ("
                        + url + ")", e);
            }
        }
        Path file = path(url, name);
        Path root = file;
        for (int i = 0; i < resource.split("/").length && root != null; i++) {
            root = root.getParent();
        }
        if (root == null) {
            throw new IllegalArgumentException("cannot tell which folder the class " + name
                    + " comes from (" + url + ")");
        }
        return root;
    }

    private static Path path(URL location, String name) {
        try {
            return Path.of(location.toURI());
        } catch (URISyntaxException | RuntimeException e) {
            throw new IllegalArgumentException("the class " + name + " comes from " + location
                    + ", which is not a folder or"
                    + " jar file the simulator can load it from", e);
        }
    }
}
