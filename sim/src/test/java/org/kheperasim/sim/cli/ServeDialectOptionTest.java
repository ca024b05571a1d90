package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** {@code serve --dialect}: a known name is served and said; an unknown one is refused, naming the known ones. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ServeDialectOptionTest {
    private String out;
    private String err;

    private int main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            return Main.commandLine().execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
    }

    @Test
    void anUnknownDialectIsRefusedNamingTheKnownOnes() {
        assertEquals(2, main("serve", "--arena", "lab", "--port", "0", "--dialect", "thymio", "--seconds", "1"));
        assertTrue(err.contains("dialect 'thymio' is not known; give one of khepera1, khepera2, epuck"), err);
    }

    @Test
    void theServedDialectIsSaid() {
        assertEquals(0, main("serve", "--arena", "lab", "--port", "0", "--dialect", "epuck", "--seconds", "0.5"));
        assertTrue(out.contains("dialect epuck: the robots answer as e-pucks do (connect with khepera-link --dialect epuck)"),
                out);
        assertEquals(0, main("serve", "--arena", "lab", "--port", "0", "--seconds", "0.5"));
        assertTrue(!out.contains("dialect"), "the default is not announced: " + out);
    }
}
