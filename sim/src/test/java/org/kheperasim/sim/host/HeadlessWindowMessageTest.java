package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A controller that opens its own window in a headless run is told where it runs: in the window, trusted. */
class HeadlessWindowMessageTest {
    @Test
    void theMessageSaysToOpenItInTheWindowAndRunItTrusted() {
        String m = ControllerFailures.HEADLESS;
        assertTrue(m.contains("khepera-sim gui --arena ... --classpath ... --controller ..."), m);
        assertTrue(m.contains("Controller > Trust this controller, then Start"), m);
        assertTrue(m.contains("--trusted"), m);
        assertTrue(m.contains("!java.awt.GraphicsEnvironment.isHeadless()"), "or guard the window: " + m);
    }
}
