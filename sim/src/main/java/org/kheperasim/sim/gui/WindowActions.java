package org.kheperasim.sim.gui;

import java.awt.event.ActionEvent;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.KeyStroke;

/**
 * The window's commands, one {@link Action} each, shared by menus, toolbar and keys. A command that
 * throws is reported in the console and the status bar; after every command the actions' enabled
 * states are brought up to date.
 */
final class WindowActions {
    private final Map<String, Action> actions = new LinkedHashMap<>();
    private final ConsolePanel console;
    private final StatusBar status;
    private Runnable refresh = () -> { };

    WindowActions(ConsolePanel console, StatusBar status) {
        this.console = console;
        this.status = status;
    }

    /** @param r what brings the enabled states up to date */
    void onRefresh(Runnable r) {
        refresh = r;
    }

    /** Bring the enabled states up to date. */
    void refresh() {
        refresh.run();
    }

    /**
     * @param key the command's key, e.g. {@code start}
     * @param name its label
     * @param tip its tool tip
     * @param accel its key, or null
     * @param body what it does
     */
    void add(String key, String name, String tip, KeyStroke accel, Runnable body) {
        Action a = new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                try {
                    body.run();
                } catch (RuntimeException ex) {
                    console.error(name + ": " + ex.getMessage());
                    status.show(name + ": " + ex.getMessage(), true);
                }
                refresh.run();
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, tip);
        if (accel != null) {
            a.putValue(Action.ACCELERATOR_KEY, accel);
        }
        actions.put(key, a);
    }

    /** @param key a command's key @return its action */
    Action get(String key) {
        Action a = actions.get(key);
        if (a == null) {
            throw new IllegalArgumentException("no window command '" + key + "'");
        }
        return a;
    }

    /** @param key a command's key @param on enabled or not */
    void enable(String key, boolean on) {
        get(key).setEnabled(on);
    }

    /** @param key a command's key @return true when there is such a command */
    boolean has(String key) {
        return actions.containsKey(key);
    }

    /** @param code a key code @param mods its modifiers @return the key stroke */
    static KeyStroke ks(int code, int mods) {
        return KeyStroke.getKeyStroke(code, mods);
    }
}
