package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.KeyEventDispatcher;
import java.awt.KeyboardFocusManager;
import java.awt.Window;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.util.Map;
import javax.swing.Action;
import javax.swing.JComboBox;
import javax.swing.SwingUtilities;
import javax.swing.text.JTextComponent;

/**
 * The run keys of the window (F5 Start, F6 Pause, F7 Step, F8 Stop, F9 Reset, F10 Reload, Space
 * Start/Pause) and the palette's letters (S, W, L, C, R), wherever the focus is in it. Swing's own
 * components take some of these keys first (a split pane F6 and F8, the menu bar F10, a focused
 * component Space, a text pane, even one that cannot be edited, every letter), so they are
 * dispatched here, before any component sees them. Space and the letters are left to a text field
 * being typed in and to a combo box.
 */
final class WindowKeys implements KeyEventDispatcher {
    private final Window window;
    private final Map<Integer, Action> keys;
    private final Action startPause;
    private final Map<Integer, Action> letters;

    private WindowKeys(Window window, Map<Integer, Action> keys, Action startPause, Map<Integer, Action> letters) {
        this.window = window;
        this.keys = keys;
        this.startPause = startPause;
        this.letters = letters;
    }

    /**
     * @param window the window whose keys these are
     * @param keys function keys (a {@link KeyEvent} VK code, no modifier) and their actions
     * @param startPause what Space does
     * @param letters letter keys (a VK code, pressed with or without Shift) and their actions
     * @return the dispatcher, to {@link #uninstall()} when the window closes
     */
    static WindowKeys install(Window window, Map<Integer, Action> keys, Action startPause,
            Map<Integer, Action> letters) {
        WindowKeys k = new WindowKeys(window, keys, startPause, letters);
        KeyboardFocusManager.getCurrentKeyboardFocusManager().addKeyEventDispatcher(k);
        return k;
    }

    void uninstall() {
        KeyboardFocusManager.getCurrentKeyboardFocusManager().removeKeyEventDispatcher(this);
    }

    @Override
    public boolean dispatchKeyEvent(KeyEvent e) {
        if (!inWindow(e.getComponent())) {
            return false;
        }
        if (letter(e)) {
            return true;
        }
        if (e.getModifiersEx() != 0) {
            return false;
        }
        Action a = keys.get(e.getKeyCode());
        if (a == null && e.getKeyCode() == KeyEvent.VK_SPACE && !typing(e.getComponent())) {
            a = startPause;
        }
        if (a == null) {
            return false;
        }
        if (e.getID() == KeyEvent.KEY_PRESSED && a.isEnabled()) {
            a.actionPerformed(new ActionEvent(e.getComponent(), ActionEvent.ACTION_PERFORMED, null));
        }
        // The release (and for Space the typed character) of a key handled here goes no farther either.
        e.consume();
        return true;
    }

    /** A palette letter, with or without Shift, where nothing is typed: chooses its tool. @return true when handled */
    private boolean letter(KeyEvent e) {
        int mods = e.getModifiersEx() & ~KeyEvent.SHIFT_DOWN_MASK;
        if (mods != 0 || typing(e.getComponent())) {
            return false;
        }
        Action a = e.getID() == KeyEvent.KEY_TYPED
                ? letters.get(KeyEvent.getExtendedKeyCodeForChar(Character.toUpperCase(e.getKeyChar())))
                : letters.get(e.getKeyCode());
        if (a == null) {
            return false;
        }
        if (e.getID() == KeyEvent.KEY_PRESSED && a.isEnabled()) {
            a.actionPerformed(new ActionEvent(e.getComponent(), ActionEvent.ACTION_PERFORMED, null));
        }
        e.consume();
        return true;
    }

    private boolean inWindow(Component c) {
        return c != null && SwingUtilities.getWindowAncestor(c) == window || c == window;
    }

    private static boolean typing(Component c) {
        return c instanceof JTextComponent t && t.isEditable() || c instanceof JComboBox<?>;
    }
}
