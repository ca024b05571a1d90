package org.kheperasim.sim.sandbox;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The simulator's own classpath as a JVM it starts must be given it: each entry of this JVM's
 * {@code java.class.path} at its real location, absolute with every symbolic link resolved. The
 * property holds what the user typed ({@code java -jar khepera-sim.jar} gives {@code khepera-sim.jar});
 * a child that runs in another folder (a sandbox's, a warm worker's scratch folder) would find
 * nothing there, and a box shows a file at its own path, not at a link's.
 */
public final class OwnClasspath {
    private OwnClasspath() {
    }

    /** @return the entries that exist, resolved, in their order, each once */
    public static List<Path> entries() {
        List<Path> out = new ArrayList<>();
        for (String e : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (e.isEmpty()) {
                continue;
            }
            Path p = Path.of(e);
            if (!Files.exists(p)) {
                continue;
            }
            Path real;
            try {
                real = p.toRealPath();
            } catch (IOException ex) {
                real = p.toAbsolutePath().normalize();
            }
            if (!out.contains(real)) {
                out.add(real);
            }
        }
        return out;
    }

    /** @return {@link #entries()} as a {@code -cp} value */
    public static String asOption() {
        StringBuilder sb = new StringBuilder();
        for (Path p : entries()) {
            sb.append(sb.length() > 0 ? File.pathSeparator : "").append(p);
        }
        return sb.toString();
    }
}
