package org.kheperasim.sim.gui;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * On a 1366 × 768 laptop screen the window opens within the screen, console included (it used to
 * open at a fixed 1180 × 900). Under Xvfb, in a child JVM ({@link WindowFitDriver}); skipped without
 * Xvfb, except in CI.
 */
class WindowFitTest {
    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowFitsALaptopScreenWithItsConsole() throws Exception {
        WindowDriverRun.run("the window size test", WindowFitDriver.class, "1366x768x24", 150, new String[] {"FIT OK",
            "SMALL WINDOW OK", "LARGE WINDOW OK"});
    }
}
