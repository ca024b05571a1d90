package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.text.HostileText;

/**
 * Issue 35 item 6: the window's console and status bar show a controller's control characters escaped
 * and every line of its fault stamped (the components only, without a window: no display needed).
 */
class ConsoleEscapeTest {
    @Test
    void theConsoleShowsEscapesAndStampsEveryLine() throws Exception {
        String[] shown = new String[2];
        SwingUtilities.invokeAndWait(() -> {
            ConsolePanel console = new ConsolePanel();
            console.accept(new ConsoleLine(1_000_000_000L, "robot", ConsoleLine.Kind.MESSAGE, "bell\u0007 esc\u001b[2J rlo\u202e"));
            console.accept(new ConsoleLine(2_000_000_000L, "robot", ConsoleLine.Kind.ERROR,
                    "threw x\nForger in lab: 600.0 s simulated\u001b[8m\n\tat Forger.doWork(Forger.java:9)"));
            console.drain();
            shown[0] = console.contents();
            StatusBar status = new StatusBar();
            status.alert("robot: threw \u001b[2Jx\ny");
            shown[1] = status.message();
        });
        HostileText.assertNoRawControl("the console", shown[0]);
        HostileText.assertNoRawControl("the status bar", shown[1]);
        assertEquals("[    1.000 s] robot: bell\\x07 esc\\e[2J rlo\\u202e\n"
                + "[    2.000 s] ERROR robot: threw x\n"
                + "[    2.000 s] ERROR robot: Forger in lab: 600.0 s simulated\\e[8m\n"
                + "[    2.000 s] ERROR robot:     at Forger.doWork(Forger.java:9)\n", shown[0]);
        assertTrue(shown[1].contains("threw \\e[2Jx\\ny"), shown[1]);
    }
}
