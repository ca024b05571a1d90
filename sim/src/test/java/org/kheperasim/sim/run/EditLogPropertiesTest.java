package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fuzz.Fuzz;
import org.kheperasim.link.fuzz.Mutations;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Engine;

/** Whatever the text, an edit log reads and writes back the same, or the error names its line. */
@Tag("properties")
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class EditLogPropertiesTest {

    private static final String SMALL = "khepera-arena 1\nname e\nsize 600 400\nrobot 100 100 90\nwall 0 4 600 4 8\ncap 300 300\n";
    private static final List<String> WORDS = List.of("@", "end", "khepera-edits 1", "khepera-arena 1", "size", "robot",
            "wall", "cap", "@ 0", "@ -1000000", "@ 1000001", "@ 9223372036854775807");

    static String input(SplittableRandom r) {
        StringBuilder b = new StringBuilder(EditLog.HEADER).append('\n');
        long t = 0;
        for (int i = 0, n = r.nextInt(4); i < n; i++) {
            t += Engine.TICK_NANOS * r.nextInt(5000);
            long stamp = r.nextInt(10) == 0 ? t + r.nextInt(3) - 1 : t;
            b.append("@ ").append(stamp).append('\n');
            b.append(i == 0 && r.nextBoolean() ? ArenaFormat.write(ArenaFormat.loadBundled("lab")) : SMALL).append("end\n");
        }
        String text = b.toString();
        return r.nextInt(3) > 0 ? Mutations.damage(r, text, WORDS, 4) : text;
    }

    static void readsOrNamesTheLine(String text) {
        EditLog log;
        try {
            log = EditLog.parse(text, "fuzz.edits");
        } catch (EditLogException e) {
            int lines = text.split("\n", -1).length;
            assertTrue(e.line() >= 1 && e.line() <= lines, "line " + e.line() + " of " + lines + ": " + e.getMessage());
            assertTrue(e.getMessage().startsWith("fuzz.edits:" + e.line() + ": "), e.getMessage());
            return;
        }
        EditLog back = EditLog.parse(log.write(), "again.edits");
        assertEquals(log.edits(), back.edits());
        long previous = 0;
        for (EditLog.Edit e : log.edits()) {
            assertTrue(e.timeNanos() >= previous && e.timeNanos() % Engine.TICK_NANOS == 0, "stamp " + e.timeNanos());
            previous = e.timeNanos();
        }
    }

    @Test
    void everyTextIsAnEditLogThatRoundTripsOrAnErrorNamingItsLine() {
        Fuzz.checkText("edit log", 500, EditLogPropertiesTest::input, EditLogPropertiesTest::readsOrNamesTheLine);
    }
}
