package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;

/** What the window drivers share: finding components by name, clicking one, asking the event thread. */
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

    /** A click near the component's top-left corner, which puts the focus there. */
    static void clickCorner(Robot robot, Component target) throws Exception {
        Point p = onEdt(() -> {
            Point o = target.getLocationOnScreen();
            return new Point(o.x + 8, o.y + 8);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    /** @return what the supplier gives, asked on the event thread */
    static <T> T onEdt(Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }
}
