package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A worker makes a submission's next run while the grader judges the one before ({@link SlotWork}): when that
 * one differs from its replay, the run made after it on the same JVM is dropped unjudged and made again on a new
 * worker, and the one that differed is made again on a JVM of its own, as when the slot waited for each verdict.
 * Each run is in the report and the journal once, with what its second making gave; nothing of a dropped making is
 * left in the work folder.
 */
class PipelinedRerunTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRunAfterOneThatDifferedIsMadeAgainOnANewWorker() throws IOException {
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        Path subs = dir.resolve("subs");
        Hostile.memoryForger(subs.resolve("tom"));
        Path out = dir.resolve("out");
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("lab"), 3, 1, out,
                GradePlan.Shard.ALL, 128, 100, 5, 3.0, false, new PrintStream(OutputStream.nullOutputStream()), false,
                box, true));
        assertEquals(3, report.runs().size());
        for (RunRecord r : report.runs()) {
            assertEquals(RunStatus.DIVERGED, r.status(), r.toString());
            assertTrue(r.madeAgain() && r.detail().startsWith("in both makings of the run: "), r.toString());
            assertTrue(!r.picture().isEmpty() && Files.isRegularFile(out.resolve(r.picture())), r.toString());
        }
        List<String> journal = Files.readAllLines(out.resolve(Journal.FILE));
        for (int seed = 1; seed <= 3; seed++) {
            String run = "\"seed\": " + seed + ",";
            assertEquals(1, journal.stream().filter(l -> l.contains("\"tom\"") && l.contains(run)).count(),
                    "seed " + seed + " once in the journal:\n" + String.join("\n", journal));
        }
        try (Stream<Path> left = Files.list(out.resolve("work/runs"))) {
            assertEquals(List.of(), left.toList(), "no trace or log of a making left");
        }
    }
}
