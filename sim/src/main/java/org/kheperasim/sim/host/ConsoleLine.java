package org.kheperasim.sim.host;

import java.util.Locale;
import org.kheperasim.sim.text.Shown;

/**
 * One line for the person watching: a controller's message, an error, or a note from the simulator.
 *
 * @param timeNanos simulated time it refers to, ns
 * @param source the robot or controller it comes from
 * @param kind what sort of line it is
 * @param text the text (may span several lines, e.g. a stack trace)
 */
public record ConsoleLine(long timeNanos, String source, Kind kind, String text) {

    /** What sort of line. */
    public enum Kind {
        /** Sent by the controller through {@code MessagePasser}. */
        MESSAGE,
        /** Something went wrong: an exception, a hang. */
        ERROR,
        /** A note from the simulator. */
        INFO
    }

    /**
     * @return the line as printed: {@code [  12.345 s] Robot: text}; a text of several lines (a stack
     *     trace, a message with line ends) gives one such line for each, every one stamped with the time
     *     and the source, so that none can pose as another's or as the simulator's result; control
     *     characters are shown escaped ({@link Shown})
     */
    public String format() {
        String prefix = kind == Kind.ERROR ? "ERROR " : "";
        return Shown.stamped(String.format(Locale.ROOT, "[%9.3f s] %s%s: ", timeNanos / 1e9, prefix, source), text);
    }
}
