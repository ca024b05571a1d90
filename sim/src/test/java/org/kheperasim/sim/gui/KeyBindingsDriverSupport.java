package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;

/** Finding components by name in the window drivers. */
final class KeyBindingsDriverSupport {
    private KeyBindingsDriverSupport() {
    }

    static Component find(Container root, String name) {
        for (Component c : root.getComponents()) {
            if (name.equals(c.getName())) {
                return c;
            }
            if (c instanceof Container k) {
                Component f = find(k, name);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }
}
