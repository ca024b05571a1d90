package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Rectangle;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * What the window drivers share: finding components by name, clicking one, asking the event thread,
 * waiting for what the window shows, and failing the driver (its JVM) with the reason.
 */
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

    /** A click near the top-left corner of what is shown of the component (scrolled or not), which puts the focus there. */
    static void clickCorner(RobotInput input, Component target) throws Exception {
        Point p = onEdt(() -> {
            Point o = target.getLocationOnScreen();
            Rectangle shown = target instanceof JComponent j ? j.getVisibleRect() : new Rectangle();
            return new Point(o.x + shown.x + 8, o.y + shown.y + 8);
        });
        input.click(p);
    }

    /** @return what the supplier gives, asked on the event thread */
    static <T> T onEdt(Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }

    /** @return what the supplier gives, asked on the event thread; a failure there is unchecked */
    static <T> T onEdtQuiet(Supplier<T> s) {
        try {
            return onEdt(s);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** Wait up to 60 s of real time until {@code done}; else fail, saying {@code what}. */
    static void waitFor(String what, BooleanSupplier done) throws InterruptedException {
        long until = System.nanoTime() + 60_000_000_000L;
        while (!done.getAsBoolean() && System.nanoTime() < until) {
            Thread.sleep(20);
        }
        check(done.getAsBoolean(), what + ": not within 60 s");
    }

    /** Unless {@code ok}: print the reason and end the driver's JVM with status 1 (its test reads both). */
    static void check(boolean ok, String why) {
        if (!ok) {
            System.out.println("FAIL: " + why);
            System.out.flush();
            System.exit(1);
        }
    }
}
