package org.kheperasim.link.robot;

import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.binding.ControllerNames;

/**
 * Finds a controller class by the names the simulator uses ({@link ControllerNames}). On the robot
 * classes load through a plain {@link URLClassLoader}, unchanged: {@code Thread.sleep} is real time.
 */
public final class ControllerLoader {
    private final List<Path> classpath;

    /** @param classpath folders and jars with the user's compiled classes (may be empty) */
    public ControllerLoader(List<Path> classpath) {
        ControllerNames.checkClasspath(classpath);
        this.classpath = List.copyOf(classpath);
    }

    /** @return the bundled controllers' simple names */
    public static List<String> bundled() {
        return ControllerNames.bundled(ControllerLoader.class.getClassLoader());
    }

    /**
     * @param name a bundled controller's simple name or a class name on the classpath
     * @return the checked controller class
     * @throws ControllerException naming what was looked for and the fix
     */
    public Class<?> load(String name) {
        List<URL> urls = new ArrayList<>();
        for (Path p : classpath) {
            try {
                urls.add(p.toUri().toURL());
            } catch (MalformedURLException e) {
                throw new ControllerException("classpath entry " + p + " is not a usable path: " + e.getMessage(), e);
            }
        }
        // Left open: the controller's classes may load more classes while it runs.
        URLClassLoader loader = new URLClassLoader(urls.toArray(new URL[0]), ControllerLoader.class.getClassLoader());
        return ControllerNames.resolve(name, loader, bundled(), classpath, "khepera-link.jar");
    }
}
