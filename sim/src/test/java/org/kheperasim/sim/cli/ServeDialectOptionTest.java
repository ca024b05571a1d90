package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code serve --dialect}: a known name is served and said; an unknown one is refused, naming the
 * known ones; without it, each robot answers in its own robot file's dialect (said when not the
 * Khepera I's).
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ServeDialectOptionTest {

    @Test
    void anUnknownDialectIsRefusedNamingTheKnownOnes() {
        Cli.Printed p = Cli.main("serve", "--arena", "lab", "--port", "0", "--dialect", "thymio", "--seconds", "1");
        assertEquals(2, p.code(), p.err());
        assertTrue(p.err().contains("dialect 'thymio' is not known; give one of khepera1, khepera2, epuck"), p.err());
    }

    @Test
    void theServedDialectIsSaid() {
        Cli.Printed epuck = Cli.main("serve", "--arena", "lab", "--port", "0", "--dialect", "epuck", "--seconds", "0.5");
        assertEquals(0, epuck.code(), epuck.err());
        assertTrue(epuck.out().contains(
                "dialect epuck: the robots answer as e-pucks do (connect with khepera-link --dialect epuck)"), epuck.out());
        Cli.Printed own = Cli.main("serve", "--arena", "lab", "--port", "0", "--seconds", "0.5");
        assertEquals(0, own.code(), own.err());
        assertTrue(!own.out().contains("dialect"), "the Khepera I's own dialect is not announced: " + own.out());
        Cli.Printed file = Cli.main("serve", "--arena", "lab", "--port", "0", "--robot-file", "epuck", "--seconds", "0.5");
        assertEquals(0, file.code(), file.err());
        assertTrue(file.out().contains("dialect epuck:"), "an e-puck answers as one without --dialect: " + file.out());
    }
}
