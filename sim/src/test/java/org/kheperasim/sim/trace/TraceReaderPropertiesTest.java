package org.kheperasim.sim.trace;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fuzz.Fuzz;
import org.kheperasim.link.fuzz.Mutations;

/** Whatever the text, the trace reader sums it up or names the line at fault. */
@Tag("properties")
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class TraceReaderPropertiesTest {

    private static final String GOLDEN;
    private static final List<String> WORDS = List.of("#", "cap", "NONE", "OPEN", "CLOSED", "FRONT", "0.000", "-1", "seed",
            "# khepera-trace 2", "# columns", "999999999999.999");

    static {
        try {
            List<String> lines = Files.readAllLines(Path.of("src", "test", "resources", "golden", "two-rooms-WallFollower.trace"));
            GOLDEN = String.join("\n", lines.subList(0, 60)) + "\n";
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static String input(SplittableRandom r) {
        String text = Mutations.damage(r, GOLDEN, WORDS, 3);
        return r.nextInt(4) == 0 ? text : text.endsWith("\n") ? text : text + "\n";
    }

    static void summarisesOrNamesTheLine(String text) {
        try {
            TraceReader.Summary s = TraceReader.parse(text, "fuzz.trace");
            assertTrue(s.robotLines() + s.capLines() <= text.split("\n", -1).length);
        } catch (TraceFormatException e) {
            int lines = text.split("\n", -1).length;
            assertTrue(e.line() >= 1 && e.line() <= lines, "line " + e.line() + " of " + lines + ": " + e.getMessage());
            assertTrue(e.getMessage().startsWith("fuzz.trace:" + e.line() + ": "), e.getMessage());
        }
    }

    @Test
    void everyTextIsSummedUpOrAnErrorNamingItsLine() {
        Fuzz.checkText("trace reader", 2000, TraceReaderPropertiesTest::input, TraceReaderPropertiesTest::summarisesOrNamesTheLine);
    }
}
