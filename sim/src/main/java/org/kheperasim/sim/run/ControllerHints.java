package org.kheperasim.sim.run;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

/**
 * What to say when a controller name or a classpath entry is wrong in one of the ways people get
 * it wrong: the case ({@code wallfollower}), a file name ({@code MyFirst.java}, {@code
 * MyFirst.class}), a path ({@code out/MyFirst}), a simple name whose class is in a package, a
 * typo; a source file or a class file given as {@code --classpath}. Each answer says what to type.
 * Only called once something failed, so it may look through the classpath's folders and jars.
 */
final class ControllerHints {
    /** The program's jar, as the hints name it. */
    private static final String JAR = "khepera-sim.jar";
    /** Most class files looked at in one classpath entry. */
    private static final int MAX_CLASSES = 20_000;
    /** How deep into a classpath folder packages are looked for. */
    private static final int MAX_DEPTH = 12;

    private ControllerHints() {
    }

    /**
     * @param entry a classpath entry that exists
     * @return why it cannot be a classpath entry and what to give instead, or null when it may be one
     *     (a folder, or a file that starts as a zip or jar does)
     */
    static String badEntry(Path entry) {
        if (Files.isDirectory(entry)) {
            return null;
        }
        String file = entry.getFileName().toString();
        if (file.endsWith(".java")) {
            String cls = file.substring(0, file.length() - ".java".length());
            return "classpath entry " + entry + " is a Java source file, not compiled classes: compile it first,"
                    + " javac -cp " + JAR + " -d out " + entry + ", then give --classpath out --controller " + cls
                    + " (or open it in the window, Controller > Open .java, or 'gui --controller " + entry
                    + "': the window compiles it)";
        }
        if (file.endsWith(".class")) {
            Path dir = entry.toAbsolutePath().getParent();
            return "classpath entry " + entry + " is a class file; give the folder the classes are in, --classpath "
                    + dir + " --controller " + file.substring(0, file.length() - ".class".length())
                    + " (for a class in a package, the folder its package folders start in, and the name"
                    + " with its package)";
        }
        if (!looksLikeZip(entry)) {
            return "classpath entry " + entry
                    + " is neither a folder nor a jar; give the folder your compiled .class files"
                    + " are in (the -d folder of javac) or a jar";
        }
        return null;
    }

    private static boolean looksLikeZip(Path p) {
        if (!Files.isRegularFile(p)) {
            return false;   // a pipe or a device: not opened (a pipe would wait for a writer for ever)
        }
        try (InputStream in = Files.newInputStream(p)) {
            byte[] head = in.readNBytes(4);
            return head.length == 4 && head[0] == 'P' && head[1] == 'K';
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * @param name the controller name as given
     * @param bundled the bundled controllers' simple names
     * @param classpath the user's classpath
     * @return what the user most likely meant and what to type, or null when nothing comes close
     */
    static String hint(String name, List<String> bundled, List<Path> classpath) {
        String n = name.strip();
        String lower = n.toLowerCase(Locale.ROOT);
        List<String> classes = classesOn(classpath);
        if (lower.endsWith(".java") || lower.endsWith(".class") || n.contains("/") || n.contains(File.separator)) {
            return fileHint(n, classes, bundled);
        }
        List<String> known = new ArrayList<>(bundled);
        known.addAll(classes);
        // The case, exactly the name otherwise.
        for (String k : known) {
            if (k.equalsIgnoreCase(n)) {
                return "did you mean " + k + "? Names are case-sensitive: type --controller " + k;
            }
        }
        // A simple name whose class is in a package.
        if (!n.contains(".")) {
            List<String> inPackages = new ArrayList<>();
            for (String c : classes) {
                if (simple(c).equalsIgnoreCase(n) && c.contains(".")) {
                    inPackages.add(c);
                }
            }
            if (!inPackages.isEmpty()) {
                return "did you mean " + String.join(" or ", inPackages)
                        + "? A class in a package is named with its package:"
                        + " type --controller " + inPackages.get(0);
            }
        }
        // A typo: the nearest name within two edits.
        String best = null;
        int bestDistance = 3;
        for (String k : known) {
            int d = StrictMath.min(distance(lower, k.toLowerCase(Locale.ROOT)),
                    distance(lower, simple(k).toLowerCase(Locale.ROOT)));
            if (d < bestDistance) {
                bestDistance = d;
                best = k;
            }
        }
        return best == null ? null : "did you mean " + best + "? Type --controller " + best;
    }

    /** A file name or a path where a class name belongs. */
    private static String fileHint(String name, List<String> classes, List<String> bundled) {
        Path p = Path.of(name);
        String file = p.getFileName() == null ? name : p.getFileName().toString();
        String cls = file.replaceFirst("(?i)\\.(java|class)$", "");
        Path dir = p.getParent();
        String known = null;
        for (String c : classes) {
            if (simple(c).equals(cls)) {
                known = c;
            }
        }
        for (String b : bundled) {
            if (b.equals(cls)) {
                known = b;
            }
        }
        if (file.toLowerCase(Locale.ROOT).endsWith(".java") && known == null) {
            return "'" + name + "' is a source file; a controller is named by its compiled class. Compile it"
                    + " first, javac -cp "
                    + JAR + " -d out " + name + ", then type --classpath out --controller " + cls
                    + " (in the window, Controller > Open .java compiles it for you)";
        }
        if (known != null) {
            return "a controller is named by its class, not by a file: type --controller " + known;
        }
        return "a controller is named by its class, not by a file: type "
                + (dir == null ? "" : "--classpath " + dir + " ")
                + "--controller " + cls + " (with its package, if it has one)";
    }

    private static String simple(String cls) {
        return cls.substring(cls.lastIndexOf('.') + 1);
    }

    /** @return the top-level classes on the classpath, with their packages (inner classes left out) */
    static List<String> classesOn(List<Path> classpath) {
        Set<String> out = new LinkedHashSet<>();
        for (Path entry : classpath) {
            if (Files.isDirectory(entry)) {
                try (Stream<Path> files = Files.walk(entry, MAX_DEPTH)) {
                    files.filter(f -> f.getFileName().toString().endsWith(".class")).limit(MAX_CLASSES)
                            .map(f -> className(entry.relativize(f).toString().replace(File.separatorChar, '/')))
                            .filter(c -> c != null).forEach(out::add);
                } catch (IOException | java.io.UncheckedIOException e) {
                    // A folder that cannot be read gives no hint; the error itself still names the classpath.
                    continue;
                }
            } else if (Files.isRegularFile(entry)) {
                try (ZipFile zip = new ZipFile(entry.toFile())) {
                    Enumeration<? extends ZipEntry> entries = zip.entries();
                    for (int i = 0; entries.hasMoreElements() && i < MAX_CLASSES; i++) {
                        String c = className(entries.nextElement().getName());
                        if (c != null) {
                            out.add(c);
                        }
                    }
                } catch (IOException e) {
                    continue;
                }
            }
        }
        return new ArrayList<>(out);
    }

    /**
     * @param path a class file's path in a folder or jar, with / @return its class name, or null for inner classes and
     *     others
     */
    private static String className(String path) {
        if (!path.endsWith(".class") || path.contains("$") || path.startsWith("META-INF/")
                || path.endsWith("module-info.class")
                || path.endsWith("package-info.class")) {
            return null;
        }
        return path.substring(0, path.length() - ".class".length()).replace('/', '.');
    }

    /** Levenshtein distance, for names of a few dozen characters. */
    static int distance(String a, String b) {
        int[] prev = new int[b.length() + 1];
        int[] cur = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            prev[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            cur[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                cur[j] = StrictMath.min(StrictMath.min(cur[j - 1] + 1, prev[j] + 1), prev[j - 1] + cost);
            }
            int[] t = prev;
            prev = cur;
            cur = t;
        }
        return prev[b.length()];
    }
}
