package org.kheperasim.link.timing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** A speed command's time on the wire is that of the line robot-link sends, {@code D,l,r} and CR. */
class LinkTimingTest {

    @Test
    void aSpeedCommandTakesTheWireTimeOfItsLine() {
        int[] speeds = {0, 1, -1, 9, -9, 10, -10, 99, 127, -128, 1000, -32768, Integer.MAX_VALUE, Integer.MIN_VALUE};
        for (int baud : new int[] {9600, 38400, 115200}) {
            LinkTiming timing = LinkTiming.atBaud(baud);
            for (int left : speeds) {
                for (int right : speeds) {
                    String line = "D," + left + "," + right + "\r";
                    assertEquals(timing.wireNanos(line.length()) + timing.turnaroundNanos(),
                            timing.speedCommandDelayNanos(left, right), line.trim() + " at " + baud + " baud");
                }
            }
        }
    }
}
