package org.kheperasim.sim.gui;

import java.awt.AWTEvent;
import java.awt.MouseInfo;
import java.awt.Point;
import java.awt.PointerInfo;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.util.ArrayDeque;
import java.util.function.Predicate;
import javax.swing.SwingUtilities;

/**
 * {@link Robot}'s mouse and keys, each gesture waited for as the window sees it: until the window
 * has dispatched the event the gesture makes, then until the event thread has finished with it.
 *
 * <p>Why not {@link Robot#waitForIdle()}: it waits for an empty event queue, which a window that
 * repaints every 12 ms (FramePainter) while it replays a long recording and plots it hardly ever
 * has, so each call ran to the toolkit's 10 s limit (ReplayWindowTest spent about 40 of its 56 s
 * there) and then went on as if all was done. Waiting for the event itself takes as long as a
 * loaded machine needs, no longer, and fails by name when the event never comes.
 */
final class RobotInput {
    /** How long a gesture may take to reach the window, ns: generous, for a machine under load. */
    private static final long LIMIT_NANOS = 30_000_000_000L;

    private final Robot robot;
    private final Object lock = new Object();
    /** The input events the window dispatched lately, newest last, each with its number. */
    private final ArrayDeque<Seen> seen = new ArrayDeque<>();
    private long seq;

    private record Seen(long seq, AWTEvent event) {
    }

    RobotInput(Robot robot) {
        this.robot = robot;
        Toolkit.getDefaultToolkit().addAWTEventListener(this::seen,
                AWTEvent.MOUSE_EVENT_MASK | AWTEvent.MOUSE_MOTION_EVENT_MASK | AWTEvent.KEY_EVENT_MASK);
    }

    Robot robot() {
        return robot;
    }

    private void seen(AWTEvent e) {
        synchronized (lock) {
            seen.addLast(new Seen(++seq, e));
            if (seen.size() > 1000) {
                seen.removeFirst();
            }
            lock.notifyAll();
        }
    }

    /** Moves the pointer to {@code p} (screen coordinates) and waits until the window has it there. */
    void move(Point p) throws Exception {
        PointerInfo now = MouseInfo.getPointerInfo();
        if (now != null && now.getLocation().equals(p)) {
            return;
        }
        long after = mark();
        robot.mouseMove(p.x, p.y);
        awaitMouse(after, "the pointer at " + p.x + "," + p.y, m -> (m.getID() == MouseEvent.MOUSE_MOVED
                || m.getID() == MouseEvent.MOUSE_DRAGGED || m.getID() == MouseEvent.MOUSE_ENTERED)
                && m.getXOnScreen() == p.x && m.getYOnScreen() == p.y);
    }

    /** Presses the left button where the pointer is and waits until the window has the press. */
    void press() throws Exception {
        long after = mark();
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        awaitMouse(after, "the button pressed", m -> m.getID() == MouseEvent.MOUSE_PRESSED);
    }

    /** Releases the left button and waits until the window has the release. */
    void release() throws Exception {
        long after = mark();
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        awaitMouse(after, "the button released", m -> m.getID() == MouseEvent.MOUSE_RELEASED);
    }

    /** A left click at {@code p}, screen coordinates, waited for. */
    void click(Point p) throws Exception {
        move(p);
        press();
        release();
    }

    /**
     * Presses {@code keys} in order (a shortcut: modifiers first) and releases them in reverse; waits
     * until the window has had the last key's press (what a key binding acts on), then for the event
     * thread.
     */
    void keys(int... keys) throws Exception {
        long after = mark();
        for (int k : keys) {
            robot.keyPress(k);
        }
        int last = keys[keys.length - 1];
        awaitKey(after, last);
        for (int i = keys.length - 1; i >= 0; i--) {
            robot.keyRelease(keys[i]);
        }
        settle();
    }

    /**
     * The event thread has handled what was posted before this call, and what that posted in turn
     * (twice round): for a state change made on it, before the state is read.
     */
    void settle() throws Exception {
        Toolkit.getDefaultToolkit().sync();
        SwingUtilities.invokeAndWait(() -> { });
        SwingUtilities.invokeAndWait(() -> { });
    }

    private long mark() {
        synchronized (lock) {
            return seq;
        }
    }

    private void awaitMouse(long after, String what, Predicate<MouseEvent> wanted) throws Exception {
        await(after, what, e -> e instanceof MouseEvent m && wanted.test(m));
        settle();
    }

    private void awaitKey(long after, int code) throws Exception {
        await(after, "the key " + KeyEvent.getKeyText(code) + " pressed (has it the focus?)",
                e -> e instanceof KeyEvent k && k.getID() == KeyEvent.KEY_PRESSED && k.getKeyCode() == code);
    }

    /** Waits until an event numbered after {@code after} is {@code wanted}. */
    private void await(long after, String what, Predicate<AWTEvent> wanted) throws InterruptedException {
        long until = System.nanoTime() + LIMIT_NANOS;
        synchronized (lock) {
            while (seen.stream().noneMatch(s -> s.seq() > after && wanted.test(s.event()))) {
                long left = until - System.nanoTime();
                if (left <= 0) {
                    throw new IllegalStateException("the window did not see " + what + " within " + LIMIT_NANOS / 1_000_000_000L
                            + " s; the last input event it saw: " + (seen.isEmpty() ? "none" : seen.getLast().event()));
                }
                lock.wait(StrictMath.max(1, left / 1_000_000));
            }
        }
    }
}
