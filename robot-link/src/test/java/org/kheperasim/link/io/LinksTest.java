package org.kheperasim.link.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

@Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class LinksTest {

    @Test
    void memoryLinkSplitsLinesAndReportsTheFarEndClosing() throws Exception {
        MemoryLink[] ends = MemoryLink.pair(LineEnd.LF, LineEnd.CRLF);
        ends[1].writeRaw("\r\nn,1");
        assertNull(ends[0].readLine(30), "half a line is not a line");
        ends[1].writeRaw(",2\r\nxx\rd\r\n");
        assertEquals("n,1,2", ends[0].readLine(100));
        assertEquals(7, ends[0].discardInput(), "the rest: LF, xx, CR, d, CR, LF");
        ends[0].writeLine("D,1,1");
        assertEquals("D,1,1", ends[1].readLine(100));
        ends[1].close();
        assertThrows(LinkClosedException.class, () -> ends[0].readLine(100));
    }

    @Test
    void aTcpLinkTalksToARobotServer() throws Exception {
        try (ServerSocket server = new ServerSocket(0)) {
            Thread accept = new Thread(() -> {
                try {
                    Socket s = server.accept();
                    new FakeKhepera(s.getInputStream(), s.getOutputStream(), null).start();
                } catch (Exception e) {
                    throw new RuntimeException(e);
                }
            });
            accept.start();
            Link link = Links.open(SerialSettings.khepera("tcp://localhost:" + server.getLocalPort(), 38400));
            try (Session s = new Session(link, LinkTiming.defaults(), Session.Options.defaults())) {
                assertEquals("5.02", s.open().bios());
                assertEquals("d", s.exchange(new Command.SetSpeed(2, 2)).encode());
                assertEquals(2, s.exchange(new Command.ReadSpeed()).intValue(0));
            }
            assertTrue(link.describe().startsWith("tcp://"));
        }
    }
}
