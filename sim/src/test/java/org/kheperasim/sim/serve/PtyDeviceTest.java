package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.RandomAccessFile;
import org.junit.jupiter.api.Test;

/**
 * The pseudo-terminal under {@code serve --pty}: a program's open shows as the hang-up going away,
 * and while the bridge locks the slave (to throw away what a client left) no program can open it,
 * so none can lose its first bytes to that flush.
 */
class PtyDeviceTest {
    @Test
    void aLockedSlaveCannotBeOpenedAndAnUnlockedOneCan() throws IOException {
        assumeTrue(System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux"), "Linux only");
        try (PtyDevice pty = PtyDevice.open()) {
            assertTrue((pty.poll(0) & PtyDevice.POLLHUP) != 0, "nobody has it open: a hang-up");
            assertTrue(pty.lockSlave(true), "the lock is known on " + System.getProperty("os.arch"));
            assertThrows(IOException.class, () -> new RandomAccessFile(pty.slavePath(), "rw").close(),
                    "a locked slave refuses an open");
            assertTrue(pty.lockSlave(false));
            try (RandomAccessFile client = new RandomAccessFile(pty.slavePath(), "rw")) {
                assertEquals(0, pty.poll(0) & PtyDevice.POLLHUP, "a program has it open: no hang-up");
                client.write("E\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
                assertEquals(PtyDevice.POLLIN, pty.poll(1000) & PtyDevice.POLLIN, "its bytes wait on the master");
            }
        }
    }

    /**
     * A reply written after its client closed waits in the slave's own buffer, where the master's flush does not
     * reach: the next program to open the pty would read it as the reply to its first command (CI saw "d").
     */
    @Test
    void aReplyLeftForAClientThatHasGoneIsThrownAwayBeforeTheNextOpens() throws Exception {
        assumeTrue(System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux"), "Linux only");
        for (boolean discard : new boolean[] {false, true}) {
            try (PtyDevice pty = PtyDevice.open()) {
                new RandomAccessFile(pty.slavePath(), "rw").close(); // a client came and went
                pty.write("d\r\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII), 3);
                Thread.sleep(100); // the line discipline takes it in
                pty.discardPending();
                if (discard) {
                    pty.discardUnreadReplies();
                }
                pty.makeRaw();
                try (java.io.FileInputStream next = new java.io.FileInputStream(pty.slavePath())) {
                    Thread.sleep(100);
                    int waiting = next.available();
                    if (discard) {
                        assertEquals(0, waiting, "nothing of the last client's reaches the next");
                    } else {
                        System.out.println("without the slave's flush, the next client finds " + waiting + " byte(s)");
                    }
                }
            }
        }
    }
}
