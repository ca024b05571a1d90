package org.kheperasim.testing;

import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds the student's source line in what the simulator reports: the first stack frame (or
 * {@code File.java:N} in a refusal) of a class that is neither the Java platform's nor the simulator's.
 * The bundled controllers count as a student's: they are examples of one.
 */
final class StudentLines {
    /** Classes whose frames are never the student's. */
    private static final List<String> NOT_THEIRS = List.of("java.", "javax.", "jdk.", "sun.", "com.sun.",
            "org.kheperasim.sim.", "org.kheperasim.api.", "org.kheperasim.link.", "org.kheperasim.testing.",
            "edu.wsu.KheperaSimulator.", "org.junit.", "org.opentest4j.", "org.objectweb.asm.", "picocli.");
    /** A stack trace's frame: {@code at pkg.Class.method(File.java:12)}. */
    private static final Pattern FRAME = Pattern.compile("at ([\\w$.]+)\\.[\\w$<>]+\\(([\\w$]+\\.java):(\\d+)\\)");
    /** A refusal's line: {@code Filer.java:5: uses java.io.File}. */
    private static final Pattern REFUSAL = Pattern.compile("\\b([\\w$]+\\.java):(\\d+):");
    /** The class that refuses a controller's escape at run time (System.exit and the like). */
    private static final String CONTAINMENT = "org.kheperasim.sim.host.Containment";

    private StudentLines() {
    }

    /**
     * @param text an error's text: a message with a stack trace, or a refusal
     * @return the first student frame's {@code File.java:N}, or empty
     */
    static Optional<String> inText(String text) {
        if (text == null) {
            return Optional.empty();
        }
        Matcher m = FRAME.matcher(text);
        while (m.find()) {
            if (theirs(m.group(1))) {
                return Optional.of(m.group(2) + ":" + m.group(3));
            }
        }
        Matcher r = REFUSAL.matcher(text);
        return r.find() ? Optional.of(r.group(1) + ":" + r.group(2)) : Optional.empty();
    }

    /**
     * The line that broke a rule, from the stack of the controller's thread as the simulator refuses the
     * call (System.exit and the like are refused on the thread that called them): the first student frame
     * below the simulator's refusal.
     *
     * @param stack the current thread's stack, innermost first
     * @return {@code File.java:N}, or empty when the stack holds no refusal
     */
    static Optional<String> belowRefusal(StackTraceElement[] stack) {
        boolean refused = false;
        for (StackTraceElement e : stack) {
            if (e.getClassName().equals(CONTAINMENT)) {
                refused = true;
            } else if (refused && theirs(e.getClassName()) && e.getFileName() != null && e.getLineNumber() > 0) {
                return Optional.of(e.getFileName() + ":" + e.getLineNumber());
            }
        }
        return Optional.empty();
    }

    /** @return true when {@code className} is not of the platform's or the simulator's */
    static boolean theirs(String className) {
        for (String p : NOT_THEIRS) {
            if (className.startsWith(p)) {
                return false;
            }
        }
        return true;
    }
}
