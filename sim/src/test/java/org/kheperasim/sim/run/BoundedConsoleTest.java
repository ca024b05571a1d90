package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.host.ConsoleLine;

/**
 * The console's budget says how much was printed and how much kept, and a fault's message (an
 * exception's message and stack trace of any size) is bounded like output, with the student's frames kept.
 */
class BoundedConsoleTest {
    @Test
    void theNoteSaysWhatWasPrintedAndWhatKept() {
        List<ConsoleLine> seen = new ArrayList<>();
        BoundedConsole console = new BoundedConsole(seen::add, 100);
        for (int i = 0; i < 1000; i++) {
            console.accept(new ConsoleLine(i, "robot", ConsoleLine.Kind.MESSAGE, "line " + (1000 + i))); // 10 characters
        }
        console.finish();
        assertEquals(10, seen.size() - 1, "10 lines of 9 characters (and their ends) fit in 100");
        assertEquals("printed 10 KB of controller output; kept the first 100 characters (the run's limit), dropped 990 lines",
                seen.get(seen.size() - 1).text());
    }

    @Test
    void aFaultOfAnySizeIsBoundedWithItsFramesKept() {
        StringBuilder trace = new StringBuilder("threw java.lang.IllegalStateException: ").append("x".repeat(5_000_000))
                .append("; the robot was stopped.\n");
        for (int i = 0; i < 200; i++) {
            trace.append("more of the message ").append(i).append('\n');
        }
        trace.append("\tat Thrower.doWork(Thrower.java:7)\n");
        for (int i = 0; i < 1000; i++) {
            trace.append("\tat Thrower.deep(Thrower.java:9)\n");
        }
        String cut = BoundedConsole.bounded(trace.toString());
        assertTrue(cut.length() <= BoundedConsole.MAX_TEXT + 100, cut.length() + " characters");
        assertTrue(cut.startsWith("threw java.lang.IllegalStateException: xxx"), cut.substring(0, 60));
        assertTrue(cut.contains("\n\tat Thrower.doWork(Thrower.java:7)\n"), "the student's frame is kept");
        assertTrue(cut.matches("(?s).*\\n\\.\\.\\. \\d+ more lines \\(5(\\.\\d)? MB cut\\)"), cut.substring(cut.length() - 80));
        String line = "a line of its own";
        assertSame(line, BoundedConsole.bounded(line), "a line within the limit is not copied");
    }

    @Test
    void aHugeErrorPastTheLimitIsKeptCut() {
        List<ConsoleLine> seen = new ArrayList<>();
        BoundedConsole console = new BoundedConsole(seen::add, 1000);
        console.accept(new ConsoleLine(1, "robot", ConsoleLine.Kind.ERROR, "threw x: " + "y".repeat(3_000_000) + "\n\tat A.b(A.java:1)"));
        console.finish();
        assertTrue(seen.get(0).text().length() < 3000, seen.get(0).text().length() + " characters");
        assertTrue(seen.get(0).text().contains("\tat A.b(A.java:1)"));
    }
}
