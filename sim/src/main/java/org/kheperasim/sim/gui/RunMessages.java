package org.kheperasim.sim.gui;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.host.HostedController;
import org.kheperasim.sim.run.RunSession;

/** What the status bar says about a run: which run it is, and which controller failed and where. */
final class RunMessages {
    private RunMessages() {
    }

    /** @return e.g. {@code Braitenberg in lab, seed 7} */
    static String described(RunSession session) {
        String cls = session.controllerClass();
        return cls.substring(cls.lastIndexOf('.') + 1) + " in " + session.arena().name() + ", seed " + session.seed();
    }

    /**
     * @param hosts the run's controllers
     * @param seconds the run's simulated time now, s
     * @return one line naming every controller that failed, how, and the student's line, or null when none did
     */
    static String failures(List<HostedController> hosts, double seconds) {
        List<String> out = new ArrayList<>();
        for (HostedController h : hosts) {
            if (!h.status().failed()) {
                continue;
            }
            Throwable t = h.failure();
            if (t != null) {
                String where = studentLine(t);
                out.add(h.name() + " threw " + t + (where == null ? "" : " at " + where));
            } else {
                String why = h.lastError();
                out.add(h.name() + " " + h.status().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ')
                        + (why == null ? "" : ": " + why));
            }
        }
        if (out.isEmpty()) {
            return null;
        }
        return String.join("; ", out)
                + String.format(java.util.Locale.ROOT, " (by t = %.3f s; the robot was stopped; the"
                + " console has the stack trace)", seconds);
    }

    /** @return the first frame of the student's code, e.g. {@code Thrower.java:9}, or null */
    static String studentLine(Throwable t) {
        for (StackTraceElement e : t.getStackTrace()) {
            String c = e.getClassName();
            if (e.getFileName() != null && e.getLineNumber() > 0 && !c.startsWith("java.") && !c.startsWith("jdk.")
                    && !c.startsWith("sun.") && !c.startsWith("org.kheperasim.api.")
                    && !c.startsWith("org.kheperasim.sim.")) {
                return e.getFileName() + ":" + e.getLineNumber();
            }
        }
        return null;
    }
}
