package org.kheperasim.sim.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.Parameters;
import org.kheperasim.sim.cli.Main;

/**
 * Evaluation at scale: the same outcomes for one thread and two, and in any order of submission;
 * parameters reach the controller; sharded outputs join into one machine's; a bad job line is an
 * outcome of its own, not the end of the evaluation.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class EvaluateTest {
    @TempDir
    Path dir;

    private static List<Job> jobs() {
        List<Job> jobs = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            Parameters p = i % 2 == 0 ? Parameters.NONE
                    : Parameters.of(Map.of("cruise", new double[] {4 + i}, "weights", new double[] {1, 1, 2, -2, -1, -i}));
            jobs.add(new Job(i, "j" + i, i == 5 ? "Braitenberg" : "StepBraitenberg", i % 3 == 0 ? "maze-easy" : "lab", i + 1,
                    20, p, i == 7 ? Map.of("noise.reading", "0.5") : Map.of(), null));
        }
        return jobs;
    }

    /** @return each outcome's facts, by job index (what a job decides: not wall time) */
    private static Map<Long, String> facts(List<Outcome> outcomes) {
        Map<Long, String> out = new TreeMap<>();
        for (Outcome o : outcomes) {
            out.put(o.job().index(), o.error() != null ? o.error() : o.result().robots() + " " + o.score());
        }
        return out;
    }

    @Test
    void theOutcomesAreTheSameForOneThreadAndTwoAndInAnyOrder() throws Exception {
        Map<Long, String> one;
        try (Evaluator e = new Evaluator(List.of(), true, 1)) {
            one = facts(e.evaluateAll(jobs()));
        }
        List<Job> shuffled = new ArrayList<>(jobs());
        Collections.shuffle(shuffled, new Random(7));
        Map<Long, String> two;
        try (Evaluator e = new Evaluator(List.of(), true, 2)) {
            two = facts(e.evaluateAll(shuffled));
        }
        assertEquals(one, two);
        assertEquals(8, one.size());
        // The parameters reach the controller: the same seed and arena, other numbers, another path.
        try (Evaluator e = new Evaluator(List.of(), true, 1)) {
            Job plain = new Job(0, "", "StepBraitenberg", "lab", 3, 20, Parameters.NONE, Map.of(), null);
            Job tuned = new Job(1, "", "StepBraitenberg", "lab", 3, 20, Parameters.of(Map.of("cruise", new double[] {10})),
                    Map.of(), null);
            Outcome a = e.evaluate(plain);
            Outcome b = e.evaluate(tuned);
            assertTrue(a.ok() && b.ok());
            assertNotEquals(a.result().first().distanceMm(), b.result().first().distanceMm(), 1.0);
        }
    }

    private static List<String> sorted(String output) {
        return output.lines().sorted().toList();
    }

    private String evaluate(String... args) {
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            int code = Main.commandLine().execute(args);
            System.out.flush();
            return code + "\n" + out.toString(StandardCharsets.UTF_8);
        } finally {
            System.setOut(old);
        }
    }

    @Test
    void slicesJoinIntoOneMachinesOutputAndABadLineIsAnOutcomeOfItsOwn() throws Exception {
        Path file = dir.resolve("jobs.jsonl");
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < 7; i++) {
            lines.add("{\"id\": \"g" + i + "\", \"seed\": " + (i + 1) + ", \"seconds\": 10"
                    + (i == 3 ? ", \"parameters\": {\"cruise\": 9}" : "") + "}");
        }
        lines.add("{\"id\": \"broken\", \"seconds\": \"ten\"}");
        Files.write(file, lines);
        String whole = evaluate("evaluate", "--jobs", file.toString(), "--controller", "StepBraitenberg", "--arena", "lab",
                "--ordered", "--threads", "2");
        assertTrue(whole.startsWith("2\n"), "a bad line makes the exit status 2: " + whole);
        assertTrue(whole.contains("\"id\":\"broken\",\"status\":\"error\",\"error\":\"line 8: \\\"seconds\\\" must be a number"),
                whole);
        // Without --ordered each outcome comes as its job ends: the same lines, in another order perhaps.
        String asTheyEnd = evaluate("evaluate", "--jobs", file.toString(), "--controller", "StepBraitenberg", "--arena", "lab",
                "--threads", "2");
        assertEquals(sorted(whole), sorted(asTheyEnd));
        List<Path> parts = new ArrayList<>();
        for (int k = 1; k <= 3; k++) {
            Path part = dir.resolve("part" + k + ".jsonl");
            evaluate("evaluate", "--jobs", file.toString(), "--controller", "StepBraitenberg", "--arena", "lab",
                    "--shard", k + "/3", "--out", part.toString(), "--threads", "1");
            parts.add(part);
        }
        List<String> args = new ArrayList<>(List.of("evaluate", "--join"));
        parts.forEach(p -> args.add(p.toString()));
        String joined = evaluate(args.toArray(new String[0]));
        assertEquals(whole.substring(whole.indexOf('\n') + 1), joined.substring(joined.indexOf('\n') + 1),
                "the slices' outputs joined are the one machine's");
    }
}
