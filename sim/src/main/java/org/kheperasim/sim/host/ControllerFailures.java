package org.kheperasim.sim.host;

import java.io.PrintWriter;
import java.io.StringWriter;

/**
 * How a controller's failure is told to the student: which kind it is, and the part of its stack trace that is theirs.
 */
final class ControllerFailures {
    private ControllerFailures() {
    }

    static final String HEADLESS = "opened a window, but this run has no display (java.awt.HeadlessException):"
            + " a controller's own windows open only in the simulator's window, and close with its run. Open it"
            + " there ('khepera-sim gui --arena ... --classpath ... --controller ...') and run it trusted: tick"
            + " Controller > Trust this controller, then Start (a controller that opens windows needs to be trusted;"
            + " --trusted is the same on the command line). To run it headless too, open the window only when"
            + " !java.awt.GraphicsEnvironment.isHeadless(). The controller was stopped and the robot's"
            + " motors set to 0.";

    static boolean isHeadless(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t.getClass().getName().equals("java.awt.HeadlessException")) {
                return true;
            }
        }
        return false;
    }

    static boolean isPolicyError(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t.getClass().getName().endsWith("ControllerPolicyError")) {
                return true;
            }
        }
        return false;
    }

    static String rootMessage(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t.getClass().getName().endsWith("ControllerPolicyError")) {
                return t.getMessage();
            }
        }
        return String.valueOf(e.getMessage());
    }

    /** How a controller's life ends for a throwable it did not catch, and what the student is told (null: nothing). */
    record Verdict(ControllerStatus status, String message) {
    }

    /**
     * @param e what the controller's thread ended with
     * @param who the controller, as the student knows it ({@code controller Name (class)})
     * @return how its life ends, and why
     */
    static Verdict verdict(Throwable e, String who) {
        if (e instanceof OutOfMemoryError) {
            return new Verdict(ControllerStatus.EXCEEDED_MEMORY,
                    who + " allocated without bound: the Java heap ran out ("
                    + e.getMessage() + "); the controller was stopped and the robot's motors set to 0. Does it keep"
                    + " adding to a list or map it never empties?");
        }
        if (isPolicyError(e)) {
            return new Verdict(ControllerStatus.BROKE_RULE, rootMessage(e) + "; the controller was stopped.");
        }
        if (e instanceof ControllerStoppedError) {
            return new Verdict(ControllerStatus.STOPPED, null);
        }
        if (isHeadless(e)) {
            return new Verdict(ControllerStatus.FAILED, who + " " + HEADLESS + "\n" + studentTrace(e));
        }
        return new Verdict(ControllerStatus.FAILED, "threw " + e + "; the robot was stopped.\n" + studentTrace(e));
    }

    /**
     * {@link #verdict}, on the controller's thread; when the throwable's own methods (its class's to
     * override: toString, getCause, printStackTrace) throw, it failed all the same, told by its class.
     */
    static Verdict verdictOrUnreadable(Throwable e, String who) {
        try {
            return verdict(e, who);
        } catch (RuntimeException | Error unreadable) {
            return new Verdict(ControllerStatus.FAILED,
                    "threw " + unreadable(e, unreadable) + "; the robot was stopped.");
        }
    }

    /**
     * @param thread the thread, as the student knows it ({@code thread 'name' that the controller started})
     * @param e what a thread the controller started ended with
     * @return what the student is told (it ended, the controller goes on), or null for the simulator's stop
     */
    static String helperThrew(String thread, Throwable e) {
        try {
            if (isHeadless(e)) {
                return thread + " " + HEADLESS.substring(0, HEADLESS.indexOf(" The controller was stopped"))
                        + " That thread ended; the controller goes on.";
            }
            if (!(e instanceof ControllerStoppedError)) {
                return thread + " threw " + e + "; that thread ended, the controller goes on.\n" + studentTrace(e);
            }
            return null;
        } catch (RuntimeException | Error unreadable) {
            return thread + " threw " + unreadable(e, unreadable) + "; that thread ended, the controller goes on.";
        }
    }

    /**
     * @param e a throwable of the controller's whose own methods threw when asked about it
     * @param why what they threw
     * @return what can be told of it without calling its methods: its class
     */
    static String unreadable(Throwable e, Throwable why) {
        return e.getClass().getName() + " (its message could not be read: its " + why.getClass().getName() + ")";
    }

    /**
     * The student's part of a stack trace, for each exception in it (the thrown one, each cause and
     * suppressed one): the frames of the simulator's own code (and reflection's) above the first
     * other frame are left out, so an API call that threw shows the student's line that called it;
     * from the first of the simulator's frames below the student's code on, the frames are what ran
     * the controller (or, a step controller run inline, another robot's code) and are cut.
     */
    static String studentTrace(Throwable e) {
        StringWriter out = new StringWriter();
        e.printStackTrace(new PrintWriter(out));
        StringBuilder kept = new StringBuilder();
        boolean seenStudent = false;
        boolean cut = false;
        for (String line : out.toString().split("\\R")) {
            String t = line.trim();
            if (!t.startsWith("at ") && !t.startsWith("...")) {
                // The exception's own line, or a "Caused by:" / "Suppressed:" one: a new section.
                seenStudent = false;
                cut = false;
                kept.append(line).append('\n');
                continue;
            }
            if (cut) {
                continue;
            }
            if (t.startsWith("...")) {
                kept.append(line).append('\n');
                continue;
            }
            if (simulatorFrame(t)) {
                cut = seenStudent;
                continue;
            }
            seenStudent = true;
            kept.append(line).append('\n');
        }
        return kept.toString().stripTrailing();
    }

    private static boolean simulatorFrame(String t) {
        return t.startsWith("at org.kheperasim.sim.") || t.startsWith("at java.base/jdk.internal.reflect.")
                || t.startsWith("at java.base/java.lang.reflect.") || t.startsWith("at java.base/java.lang.Thread.run")
                || t.startsWith("at java.base/java.lang.VirtualThread.");
    }

    /**
     * @param who the controller, named with its class
     * @param nowNanos its simulated time, ns
     * @param thread where it hung: empty for its own thread, else which thread it started
     * @param realSeconds the real time it ran without an API call
     * @param returnsAtOnce its {@code doWork()} keeps returning without a robot call (rather than looping inside)
     * @return the message for a controller the watchdog found hung
     */
    static String hung(String who, long nowNanos, String thread, double realSeconds, boolean returnsAtOnce) {
        if (returnsAtOnce) {
            return String.format(java.util.Locale.ROOT,
                    "controller %s stopped making API calls at simulated time %.3f s: its doWork() returns without"
                            + " reading a sensor, setting a motor or sleeping, and is called again at once,"
                            + " so no simulated time can pass (an empty doWork() does this; it went on for %.1f s of"
                            + " real time). Give doWork() its work, or end it with sleepMillis(100) to wait. The"
                            + " controller was stopped and the robot's motors set to 0.",
                    who, nowNanos / 1e9, realSeconds);
        }
        return String.format(java.util.Locale.ROOT,
                "controller %s stopped making API calls at simulated time %.3f s%s: it ran for %.1f s of"
                        + " real time without reading a sensor, setting a motor or sleeping. A loop that waits for"
                        + " something must read a sensor or call Thread.sleep inside it. The controller was"
                        + " stopped and the robot's motors set to 0.",
                who, nowNanos / 1e9, thread, realSeconds);
    }
}
