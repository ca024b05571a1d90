package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The journal keeps every finished run, drops a torn last line, and refuses another grading's. */
class JournalTest {
    private static final GradePlan PLAN = new GradePlan(List.of("alice", "bob"), List.of("maze"), 2);

    @TempDir
    Path dir;

    private static RunRecord run(GradePlan.Job j) {
        return new RunRecord(j.student(), j.arena(), j.seed(), RunStatus.OK, 12.5, 100, 12.5, 20, "Robot", "visit c*: 3/25",
                "img/" + ReportFiles.runId(j) + ".png", RunRecord.SANDBOX);
    }

    @Test
    void aTornLastLineIsDroppedAndTheRestKept() throws IOException {
        String id = Journal.identity(PLAN, GradePlan.Shard.ALL, "seconds=20");
        List<GradePlan.Job> jobs = PLAN.jobs();
        try (Journal j = Journal.open(dir, id)) {
            j.add(jobs.get(0), new Journal.Entry(run(jobs.get(0)), 1.5));
            j.add(jobs.get(2), new Journal.Entry(run(jobs.get(2)), 2.25));
        }
        Path file = dir.resolve(Journal.FILE);
        // killed while writing the next line
        Files.writeString(file, "{\"index\": 1, \"wallSeconds\": 1.0, \"run\": {\"student\": \"al", StandardCharsets.UTF_8,
                StandardOpenOption.APPEND);
        try (Journal j = Journal.open(dir, id)) {
            assertEquals(List.of(0, 2), List.copyOf(j.done().keySet()));
            assertEquals(run(jobs.get(2)), j.done().get(2).record());
            assertEquals(2.25, j.done().get(2).wallSeconds());
            j.add(jobs.get(1), new Journal.Entry(run(jobs.get(1)), 1.0));
        }
        List<String> lines = Files.readAllLines(file);
        assertEquals(4, lines.size(), "the torn line is gone, the new one whole: " + lines);
        try (Journal j = Journal.open(dir, id)) {
            assertEquals(List.of(0, 1, 2), List.copyOf(j.done().keySet()));
        }
    }

    @Test
    void anotherGradingsJournalIsRefusedWithTheFix() {
        try (Journal j = Journal.open(dir, Journal.identity(PLAN, GradePlan.Shard.ALL, "seconds=20"))) {
            j.add(PLAN.jobs().get(0), new Journal.Entry(run(PLAN.jobs().get(0)), 1));
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Journal.open(dir, Journal.identity(PLAN, GradePlan.Shard.ALL, "seconds=30")));
        assertTrue(e.getMessage().contains("holds the journal of another grading") && e.getMessage().contains("delete"),
                e.getMessage());
    }
}
