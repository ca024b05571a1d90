package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.cli.Main;

/**
 * A grading in which every run failed for one reason (a class of zeros) says so in one line on standard
 * error, naming the reason and the likely fix, and {@code grade} exits non-zero; a class whose runs
 * failed for their own reasons, or one student's runs alike, is graded as it is, exit status 0.
 */
class CommonFailureTest {
    @TempDir
    Path dir;

    @Test
    void aGradingWhoseEveryRunFailedAlikeExitsNonZeroSayingWhy() throws Exception {
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("alice"));
        Files.createDirectories(subs.resolve("bob"));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        int code;
        try {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            code = Main.commandLine().execute("grade", "--submissions", subs.toString(), "--arenas", "lab", "--seeds", "2",
                    "--out", dir.resolve("out").toString(), "--no-sandbox");
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(1, code, text);
        String last = text.strip().lines().reduce((a, b) -> b).orElse("");
        assertEquals("khepera-sim: error: every run of this grading failed the same way (4 runs of 2 students): nothing"
                + " handed in: the folder is empty; check --submissions: it must hold one folder per student with the"
                + " student's .java or .class files", last);
    }

    @Test
    void theClassNotFoundOfEveryRunNamesTheJar() {
        List<RunRecord> runs = List.of(error("alice", "Explorer"), error("bob", "Turns"));
        String line = CommonFailure.of(runs).orElseThrow();
        assertTrue(line.startsWith("every run of this grading failed the same way (2 runs of 2 students): error: exit status 1:"
                + " Caused by: java.lang.ClassNotFoundException: org.kheperasim.sim.cli.Main; the runs' JVMs did not find"
                + " the simulator's classes: grade with the jar"), line);
        assertTrue(CommonFailure.of(List.of(error("alice", "Explorer"))).isPresent(), "the grader's own error, even for one");
    }

    @Test
    void runsThatFailForTheirOwnReasonsOrOneStudentsAreNoCommonFailure() {
        RunRecord threw = new RunRecord("alice", "lab", 1, RunStatus.THREW, 0, 100, 0, 1, "Explorer",
                "java.lang.IllegalStateException: no at Explorer.java:12", "", RunRecord.SANDBOX);
        RunRecord threwToo = new RunRecord("alice", "lab", 2, RunStatus.THREW, 0, 100, 0, 1, "Explorer",
                "java.lang.IllegalStateException: no at Explorer.java:12", "", RunRecord.SANDBOX);
        assertTrue(CommonFailure.of(List.of(threw, threwToo)).isEmpty(), "one student's runs alike are the student's");
        RunRecord ok = new RunRecord("bob", "lab", 1, RunStatus.OK, 5, 100, 5, 600, "Turns", "", "", RunRecord.SANDBOX);
        assertTrue(CommonFailure.of(List.of(error("alice", "Explorer"), ok)).isEmpty());
        RunRecord hung = new RunRecord("bob", "lab", 1, RunStatus.HUNG, 0, 100, 0, 3, "Turns",
                "controller Turns stopped making API calls", "", RunRecord.SANDBOX);
        assertTrue(CommonFailure.of(List.of(error("alice", "Explorer"), hung)).isEmpty());
    }

    private static RunRecord error(String student, String controller) {
        return new RunRecord(student, "lab", 1, RunStatus.ERROR, 0, 100, 0, 0, controller,
                "exit status 1: Caused by: java.lang.ClassNotFoundException: org.kheperasim.sim.cli.Main", "",
                RunRecord.SANDBOX);
    }
}
