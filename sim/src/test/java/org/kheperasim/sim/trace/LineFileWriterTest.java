package org.kheperasim.sim.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class LineFileWriterTest {

    @Test
    void onlyWholeLinesReachTheFileWhileItIsOpen(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("t.trace");
        try (LineFileWriter w = LineFileWriter.open(file)) {
            w.write("# head\nfirst ");
            w.flush();
            assertEquals("# head\n", Files.readString(file), "a flush writes whole lines only");
            w.write("line\nsecond");
            long end = System.nanoTime() + 30_000_000_000L;
            while (!Files.readString(file).contains("first line") && System.nanoTime() < end) {
                Thread.sleep(50);
            }
            assertEquals("# head\nfirst line\n", Files.readString(file), "the flusher wrote the whole lines, no more");
            w.write(" ünïcode\n");
        }
        assertEquals("# head\nfirst line\nsecond ünïcode\n", Files.readString(file));
    }

    @Test
    void aLargeBufferIsWrittenBeforeTheFlusherComes(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("big.trace");
        try (LineFileWriter w = LineFileWriter.open(file)) {
            String line = "x".repeat(99) + "\n";
            for (int i = 0; i < 5000; i++) {
                w.write(line);
            }
            assertTrue(Files.size(file) >= 200_000 && Files.size(file) % 100 == 0, "whole lines: " + Files.size(file));
        }
        assertEquals(500_000, Files.size(file));
    }

    @Test
    void writingAfterCloseIsAnError(@TempDir Path dir) throws IOException {
        LineFileWriter w = LineFileWriter.open(dir.resolve("c.trace"));
        w.close();
        w.close();
        assertThrows(IOException.class, () -> w.write("late\n"));
    }
}
