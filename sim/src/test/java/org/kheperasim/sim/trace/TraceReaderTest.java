package org.kheperasim.sim.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class TraceReaderTest {

    static Stream<Path> goldenTraces() throws IOException {
        Path dir = Path.of("src", "test", "resources", "golden");
        try (Stream<Path> s = Files.list(dir)) {
            List<Path> traces = s.filter(p -> p.toString().endsWith(".trace")).sorted().toList();
            assertTrue(traces.size() >= 6, "the golden traces are there: " + traces);
            return traces.stream();
        }
    }

    @ParameterizedTest
    @MethodSource("goldenTraces")
    void readsEveryGoldenTrace(Path trace) {
        TraceReader.Summary s = TraceReader.read(trace);
        assertTrue(s.header().get("sample-ms").matches("\\d+"), s.header().toString());
        assertTrue(s.robotLines() > 100, "robot lines: " + s.robotLines());
        assertTrue(s.lastSeconds() > 10, "last time: " + s.lastSeconds());
    }

    @Test
    void namesTheLineAtFault() {
        String head = "# khepera-trace 2\n# seed 1\n# arena lab sha256=x\n# controller C\n# settings defaults\n"
                + "# sample-ms 50\n# columns t_s robot ...\n# caps t_s cap id x_mm y_mm held_by\n";
        String robot = "0.000 0 150.000 150.000 90.000 0 0 0 0 NONE 15 14 13 12 11 10 9 8 480 480 480 480 480 480 480 480"
                + " 180 OPEN 0 -1\n";
        assertEquals(2, TraceReader.parse(head + robot + robot.replace("0.000 0", "0.050 0") + "0.050 cap 0 1.000 2.000 -1\n",
                "ok.trace").robotLines());
        TraceFormatException cut = assertThrows(TraceFormatException.class,
                () -> TraceReader.parse(head + robot + robot.substring(0, 40), "cut.trace"));
        assertEquals(10, cut.line());
        assertTrue(cut.getMessage().startsWith("cut.trace:10: the last line is not whole"), cut.getMessage());
        TraceFormatException order = assertThrows(TraceFormatException.class,
                () -> TraceReader.parse(head + robot.replace("0.000 0", "1.000 0") + robot, "order.trace"));
        assertEquals(10, order.line());
        TraceFormatException column = assertThrows(TraceFormatException.class,
                () -> TraceReader.parse(head + robot.replace("NONE", "BUMP"), "c.trace"));
        assertTrue(column.getMessage().startsWith("c.trace:9: contact is 'BUMP'"), column.getMessage());
        TraceFormatException noSeed = assertThrows(TraceFormatException.class,
                () -> TraceReader.parse(head.replace("# seed 1\n", ""), "h.trace"));
        assertTrue(noSeed.getMessage().contains("no 'seed' field"), noSeed.getMessage());
    }
}
