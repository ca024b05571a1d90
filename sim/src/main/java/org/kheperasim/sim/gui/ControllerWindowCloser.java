package org.kheperasim.sim.gui;

import java.awt.Window;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Set;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.host.ControllerWindows;

/**
 * Closes the windows a run's controllers opened when the run ends: every window that appeared
 * during the run and is not owned by a window that was already open (the simulator's own dialogs
 * are owned by its frame, so they stay).
 */
final class ControllerWindowCloser implements ControllerWindows {

    /** Use it for every run from now on. */
    static void install() {
        ControllerWindows.Installed.set(new ControllerWindowCloser());
    }

    @Override
    public Object mark() {
        Set<Window> open = Collections.newSetFromMap(new IdentityHashMap<>());
        Collections.addAll(open, Window.getWindows());
        return open;
    }

    @Override
    public void closeSince(Object mark) {
        @SuppressWarnings("unchecked")
        Set<Window> before = (Set<Window>) mark;
        if (before == null) {
            return;
        }
        Runnable close = () -> {
            for (Window w : Window.getWindows()) {
                if (w.isDisplayable() && !before.contains(w) && !ownedByAnyOf(w, before)) {
                    w.dispose();
                }
            }
        };
        if (SwingUtilities.isEventDispatchThread()) {
            close.run();
        } else {
            SwingUtilities.invokeLater(close);
        }
    }

    /** Swing's hidden owner of dialogs created without one is no real owner. */
    private static boolean ownedByAnyOf(Window w, Set<Window> windows) {
        for (Window o = w.getOwner(); o != null; o = o.getOwner()) {
            if (windows.contains(o) && !o.getClass().getName().contains("SharedOwnerFrame")) {
                return true;
            }
        }
        return false;
    }
}
