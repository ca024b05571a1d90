package org.kheperasim.sim.grade;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A failed controller told as the report an instructor sends back tells it: where in the student's
 * code it threw ({@code Thrower.doWork(Thrower.java:9)}, as the window and {@code run} show it), and
 * the simulator's message without what depends on the machine (real seconds, the heap's fill), so
 * that the same submission gives the same report on any machine and sharded gradings merge byte for
 * byte.
 */
public final class FailureText {
    /** A frame of a printed stack trace: {@code at [loader/][module/]class.method(File.java:9)}. */
    private static final Pattern FRAME =
            Pattern.compile("^\\s*at (?:\\S*/)?([\\w$.]+)\\.([\\w$<>]+)\\(([^():]+:\\d+)\\)\\s*$");
    private static final String[] NOT_STUDENT = {"java.", "javax.", "jdk.", "sun.", "com.sun.", "org.kheperasim.sim.",
        "org.kheperasim.api."};

    private FailureText() {
    }

    /**
     * @param consoleText the simulator's error text for a controller that threw: a first line
     *     ({@code threw ...; the robot was stopped.}) and the student's part of the stack trace
     * @return the first frame of the controller's own code, e.g. {@code Thrower.doWork(Thrower.java:9)}
     *     (frames of the JDK, of the simulator and of the student API are skipped: an exception thrown
     *     inside {@code ArrayList.get} names the student's line that called it), or null when it has none
     */
    public static String studentFrame(String consoleText) {
        if (consoleText == null) {
            return null;
        }
        for (String line : consoleText.split("\\R")) {
            Matcher m = FRAME.matcher(line);
            if (m.matches() && student(m.group(1))) {
                return m.group(1) + "." + m.group(2) + "(" + m.group(3) + ")";
            }
        }
        return null;
    }

    private static boolean student(String className) {
        for (String p : NOT_STUDENT) {
            if (className.startsWith(p)) {
                return false;
            }
        }
        return true;
    }

    /**
     * @param message the simulator's message for a controller that hung, broke a rule or ran out of memory
     * @return its useful part: without the real time it ran (it differs between machines; {@code
     *     --hang-timeout} is the grading's), the heap's figures, and the closing words on stopping the
     *     robot (every failed run's robot was stopped)
     */
    public static String machineFree(String message) {
        String s = message.replaceAll("\\s*\\([^()]*\\bMB\\b[^()]*\\)", "")
                .replaceAll("for \\d+(?:\\.\\d+)? s of real time", "for longer than the hang timeout");
        for (String end : new String[] {"; the controller was stopped", ". The controller was stopped",
                "; the robot was stopped"}) {
            int cut = s.indexOf(end);
            if (cut > 0) {
                s = s.substring(0, cut) + (end.startsWith(".") ? "." : "");
            }
        }
        return s.strip();
    }
}
