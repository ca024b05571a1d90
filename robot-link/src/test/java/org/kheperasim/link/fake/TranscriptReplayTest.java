package org.kheperasim.link.fake;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.io.LineEnd;
import org.kheperasim.link.io.Link;
import org.kheperasim.link.io.TcpLink;

/**
 * The recorded transcripts of each dialect (test resources, from the manuals and the firmware)
 * replayed against the fakes: the Khepera I's and II's against the fake Khepera, the e-puck's against
 * the fake e-puck written from its firmware. The sim module replays the same ones against {@code serve}.
 */
@Timeout(60)
class TranscriptReplayTest {

    private static int replay(String transcript, OnSocket<?> robot) throws Exception {
        int port = Integer.parseInt(robot.url().replaceAll(".*:", ""));
        try (Link link = TcpLink.connect("127.0.0.1", port, LineEnd.LF, 5000)) {
            return Transcript.load(transcript).replay(link, 2000);
        }
    }

    @Test
    void theKheperaTranscriptsReplayAgainstTheFakeKhepera() throws Exception {
        for (String name : new String[] {"khepera1", "khepera2"}) {
            try (OnSocket<FakeKhepera> robot = OnSocket.start((in, out) -> new FakeKhepera(in, out, null).start())) {
                int checked = replay(name, robot);
                assertEquals(Transcript.load(name).exchanges().size(), checked, name + ": one reply line per command");
                assertTrue(checked >= 22, name + ": every command of Appendix A and the errors: " + checked);
            }
        }
    }

    @Test
    void theEpuckTranscriptReplaysAgainstTheFakeEpuck() throws Exception {
        try (OnSocket<FakeEpuck> robot = OnSocket.start((in, out) -> new FakeEpuck(in, out).start())) {
            int checked = replay("epuck", robot);
            assertTrue(checked >= 20, "checked " + checked);
            assertTrue(robot.robot().received().contains("d,10,10"));
        }
    }

    @Test
    void aReplyThatDiffersFailsTheReplay() throws Exception {
        // The e-puck's transcript against a Khepera: its first command (V) is not the Khepera's.
        try (OnSocket<FakeKhepera> robot = OnSocket.start((in, out) -> new FakeKhepera(in, out, null).start())) {
            AssertionError e = assertThrows(AssertionError.class, () -> replay("epuck", robot));
            assertEquals("epuck: 'V' should get 'v,Version 1.1.3 September 2006', got 'Command not found'", e.getMessage());
        }
    }

    @Test
    void patternsMatchIntegersWhereTheyHaveAHash() {
        assertTrue(Transcript.matches("q,#,#", "q,-12,40"));
        assertTrue(!Transcript.matches("q,#,#", "q,1"));
        assertTrue(!Transcript.matches("q,#,#", "h,1,2"));
        assertTrue(!Transcript.matches("n,#", "n,x"));
    }
}
