package org.kheperasim.sim.gui;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The run keys work wherever the focus is: a real keyboard (java.awt.Robot under Xvfb, in a child
 * JVM, {@link KeyBindingsDriver}) presses F5, F6, F7, F8, F10 and Space with the focus in the arena
 * view and in the console; then, with an unsaved edit, Ctrl+Q asks first (Cancel keeps the window,
 * Discard closes it). Skipped without Xvfb, except in CI.
 */
class KeyBindingsTest {
    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void f5F6F7F8F10AndSpaceWorkWhereverTheFocusIs() throws Exception {
        WindowDriverRun.run("the key bindings test", KeyBindingsDriver.class, null, 150,
                new String[] {"KEYS OK", "SAVE PROMPT OK"});
    }
}
