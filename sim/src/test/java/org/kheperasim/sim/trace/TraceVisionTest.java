package org.kheperasim.sim.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.VisionView;

/**
 * The trace records the images a robot's vision turret gave its controller: a vision line whenever
 * a new one was taken, which the reader checks and the diff compares like any sample.
 */
class TraceVisionTest {
    private static RobotView robot(long t) {
        return new RobotView(0, "r", 100, 100, 0, 0, 0, 0, 0, Contact.NONE, new int[8], new int[8], 0, 0, "running",
                new GripperView(180, false, org.kheperasim.api.GripperState.OPEN, false, 0, -1), 0);
    }

    private static int[] image(int grey) {
        int[] p = new int[64];
        Arrays.fill(p, grey);
        p[20] = 255;
        return p;
    }

    private static String trace(int grey) {
        Map<String, String> header = new LinkedHashMap<>();
        for (String k : TraceReader.REQUIRED) {
            if (!k.equals("columns") && !k.equals("caps")) {
                header.put(k, "x");
            }
        }
        StringWriter out = new StringWriter();
        try (TraceWriter w = new TraceWriter(out, header)) {
            w.onSnapshot(new Snapshot(0, List.of(robot(0)), List.of()));
            VisionView first = new VisionView(0, 20_000_000L, image(10));
            w.onSnapshot(new Snapshot(50_000_000L, List.of(robot(50)), List.of(), List.of(first)));
            w.onSnapshot(new Snapshot(100_000_000L, List.of(robot(100)), List.of(), List.of(first)));
            w.onSnapshot(new Snapshot(150_000_000L, List.of(robot(150)), List.of(),
                    List.of(new VisionView(0, 120_000_000L, image(grey)))));
        }
        return out.toString();
    }

    @Test
    void aNewImageGetsAVisionLineThatTheReaderChecks() {
        String text = trace(10);
        List<String> vision = text.lines().filter(l -> l.startsWith("# vision ")).toList();
        assertEquals(2, vision.size(), "one line per image taken, not per sample: " + text);
        assertTrue(vision.get(0).startsWith("# vision 0.050 0 0.020 10 10 "), vision.get(0));
        TraceReader.Summary s = TraceReader.parse(text, "t.trace");
        assertEquals(2, s.visionLines());
        assertEquals(4, s.robotLines());
        assertTrue(TraceDiff.compare(text, text).identical());
        TraceDiff.Result d = TraceDiff.compare(text, trace(11));
        assertTrue(d.firstSample() != null && d.firstSample().contains("vision turret's image"), "" + d);
        assertTrue(d.header().isEmpty(), "a vision line is a sample, not a header field: " + d.header());
    }

    @Test
    void aDamagedVisionLineIsNamed() {
        String text = trace(10).replace(" 10 10 10 ", " 10 999 10 ");
        TraceFormatException e = assertThrows(TraceFormatException.class, () -> TraceReader.parse(text, "t.trace"));
        assertTrue(e.getMessage().contains("grey level is 0..255"), e.getMessage());
    }
}
