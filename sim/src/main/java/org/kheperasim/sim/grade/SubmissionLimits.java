package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * What one hand-in may hold before the grader reads any of it: so many files, class files, jars and
 * {@code .java} sources of a size a controller has (a few KB each), so many bytes of them in all. A
 * folder past a limit (a 3 GB sparse class file, a million files) is that submission's failure, with
 * its reason; it is checked with the file system's sizes alone, nothing is read, so it costs the
 * grader neither memory nor time, and the other submissions are graded.
 */
final class SubmissionLimits {
    /** Files and folders in one hand-in, at most. */
    static final int MAX_ENTRIES = 5000;
    /** One class file, bytes (the class file format's own limits make a real one far smaller). */
    static final long MAX_CLASS = 4L << 20;
    /** One jar, bytes. */
    static final long MAX_JAR = 16L << 20;
    /** One {@code .java} source, bytes. */
    static final long MAX_SOURCE = 1L << 20;
    /** Class files, jars and sources together, bytes. */
    static final long MAX_CODE = 32L << 20;
    /** How deep the grader looks into a hand-in's folders (as {@link Submissions} does). */
    static final int DEPTH = 16;

    private SubmissionLimits() {
    }

    /**
     * @param folder a student's folder
     * @return why it is past a limit, one line naming the file (relative to the folder), its size and the
     *     fix; null when it is within them all
     * @throws IOException if the folder cannot be listed
     */
    static String check(Path folder) throws IOException {
        int entries = 0;
        long code = 0;
        try (Stream<Path> s = Files.walk(folder, DEPTH)) {
            Iterator<Path> it = s.iterator();
            while (it.hasNext()) {
                Path p = it.next();
                if (++entries > MAX_ENTRIES) {
                    return "the folder holds more than " + MAX_ENTRIES + " files and folders; hand in the controller's"
                            + " .java files (or its .class files) alone";
                }
                String name = p.getFileName().toString();
                long max = name.endsWith(".class") ? MAX_CLASS : name.endsWith(".jar") ? MAX_JAR
                        : name.endsWith(".java") ? MAX_SOURCE : -1;
                if (max < 0 || !Files.isRegularFile(p)) {
                    continue;
                }
                long size = Files.size(p);
                String shown = folder.relativize(p).toString().replace('\\', '/');
                if (size > max) {
                    return shown + " is " + size(size) + ", over the limit of " + size(max) + " for a "
                            + (max == MAX_CLASS ? "class file" : max == MAX_JAR ? "jar" : ".java source")
                            + "; a controller's files are a few KB: hand in its own sources or classes only";
                }
                code += size;
                if (code > MAX_CODE) {
                    return "its class files, jars and sources pass " + size(MAX_CODE) + " together (at " + shown
                            + "); hand in the controller's own files only";
                }
            }
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
        return null;
    }

    /** @return a size as people read it: bytes, KiB, MiB or GiB */
    static String size(long bytes) {
        if (bytes < 10_000) {
            return bytes + " bytes";
        }
        String[] units = {"KiB", "MiB", "GiB", "TiB"};
        double v = bytes / 1024.0;
        int u = 0;
        while (v >= 1024 && u < units.length - 1) {
            v /= 1024;
            u++;
        }
        return String.format(Locale.ROOT, v < 10 ? "%.1f %s" : "%.0f %s", v, units[u]);
    }
}
