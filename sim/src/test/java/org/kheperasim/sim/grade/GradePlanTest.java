package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.task.Score;

/** The plan's order and its shards: every run once, in a fixed order, whatever N. */
class GradePlanTest {
    private final GradePlan plan = new GradePlan(List.of("alice", "bob", "carol"), List.of("maze", "two-rooms"), 5);

    @Test
    void shardsCoverEveryRunOnce() {
        assertEquals(30, plan.jobs().size());
        for (int n = 1; n <= 7; n++) {
            List<GradePlan.Job> all = new ArrayList<>();
            for (int k = 1; k <= n; k++) {
                List<GradePlan.Job> shard = plan.shard(new GradePlan.Shard(k, n));
                assertTrue(shard.size() >= 30 / n && shard.size() <= 30 / n + 1, "shards share evenly");
                all.addAll(shard);
            }
            all.sort(Comparator.comparingInt(GradePlan.Job::index));
            assertEquals(plan.jobs(), all);
        }
        assertEquals(new GradePlan.Job(7, "alice", "two-rooms", 3), plan.jobs().get(7));
    }

    @Test
    void aShardIsParsedOrRefusedWithTheFix() {
        assertEquals(new GradePlan.Shard(3, 8), GradePlan.Shard.parse("3/8"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GradePlan.Shard.parse("9/8")).getMessage()
                .contains("1 <= K <= N"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GradePlan.Shard.parse("0/8")).getMessage()
                .contains("1 <= K <= N"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GradePlan.Shard.parse("three")).getMessage()
                .contains("give K/N"));
    }

    @Test
    void childResultsMapStatusesAndDropMachineNumbers() {
        GradePlan.Job job = plan.jobs().get(0);
        RunRecord killed = ChildResults.noResult(job, "Robot", true, 60, 137, "seed 1\n", RunRecord.SANDBOX);
        assertEquals(RunStatus.HUNG, killed.status());
        assertTrue(killed.detail().contains("wall-clock limit of 60 s"), killed.detail());
        RunRecord ended = ChildResults.noResult(job, "Robot", false, 60, ChildSide.WALL_LIMIT_EXIT, "", RunRecord.SANDBOX);
        assertEquals(RunStatus.HUNG, ended.status(), "a run that ended itself at its wall-clock limit");
        RunRecord oom = ChildResults.noResult(job, "Robot", false, 60, 1, "Exception: java.lang.OutOfMemoryError: Java heap space\n",
                RunRecord.SANDBOX);
        assertEquals(RunStatus.EXCEEDED_MEMORY, oom.status());
        RunRecord refused = ChildResults.noResult(job, "Robot", false, 60, 2,
                "khepera-sim: error: controller Robot was refused: Robot.java:3: uses java.io.File.delete\n", RunRecord.SANDBOX);
        assertEquals(RunStatus.BROKE_RULE, refused.status());
        RunRecord exitZero = ChildResults.noResult(job, "Robot", false, 60, 0, "", RunRecord.SANDBOX);
        assertEquals(RunStatus.TAMPERED, exitZero.status(), "success without a whole log: the simulator did not end the JVM");
        RunRecord crashed = ChildResults.noResult(job, "Robot", false, 60, 134, "# A fatal error has been detected\n",
                RunRecord.NO_SANDBOX);
        assertEquals(RunStatus.ERROR, crashed.status());
        assertTrue(crashed.detail().startsWith("killed by signal 6 (exit status 134)"), crashed.detail());
        assertEquals("controller Hog (Hog) allocated without bound", ChildResults.fault(
                "[    0.002 s] ERROR Hog: controller Hog (Hog) allocated without bound (102 of 123 MB of the heap still in use"
                        + " after a garbage collection); the controller was stopped and the robot's motors set to 0."));
        Map<String, Object> claim = Map.of("robots", List.of(Map.of("controllerStatus", "stopped")));
        Score score = new Score(List.of(new Score.Part("task visit c*", 0.1235, 12.345, 100, "3/25 regions")), 12.345, 100);
        RunRecord ok = ChildResults.fromClaim(job, "Robot", claim, score, 60, "[  60.000 s] khepera-sim: printed 1.1 MB of"
                + " controller output; kept the first 1 MB (the run's limit), dropped 12 lines; the last 8 error lines past it"
                + " are above\n", RunRecord.SANDBOX);
        assertEquals(new RunRecord("alice", "maze", 1, RunStatus.OK, 12.35, 100, 12.35, 60, "Robot",
                "visit c*: 3/25 regions | printed 1.1 MB; kept the first 1 MB", "",
                RunRecord.SANDBOX), ok);
    }
}
