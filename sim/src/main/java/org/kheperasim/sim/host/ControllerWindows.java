package org.kheperasim.sim.host;

/**
 * What a run does with the windows its controllers open (a WSU controller's own debug frame, say).
 * Headless there are none; the simulator's window installs an implementation that closes them when
 * the run ends, so a controller's window never outlives its run. The engine and the host know no
 * toolkit: this is the seam.
 */
public interface ControllerWindows {
    /** Nothing to do: no display. */
    ControllerWindows NONE = new ControllerWindows() {
        @Override
        public Object mark() {
            return null;
        }

        @Override
        public void closeSince(Object mark) {
            // no windows
        }
    };

    /** @return a mark of the windows open now, taken before the run's controllers are constructed */
    Object mark();

    /**
     * Close the windows opened since {@code mark} (and the windows they own), but none that belongs
     * to a window open then.
     *
     * @param mark what {@link #mark()} returned
     */
    void closeSince(Object mark);

    /** The implementation in use: {@link #NONE} until the window installs its own. */
    final class Installed {
        private static volatile ControllerWindows current = NONE;

        private Installed() {
        }

        /** @return the implementation in use */
        public static ControllerWindows get() {
            return current;
        }

        /** @param windows the implementation to use from now on */
        public static void set(ControllerWindows windows) {
            current = windows == null ? NONE : windows;
        }
    }
}
