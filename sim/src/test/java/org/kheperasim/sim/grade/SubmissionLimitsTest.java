package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * One hand-in cannot stop a class: a 3 GB sparse class file beside one student's controller (which
 * ran the grader out of memory while it loaded the classes, before any run: no report for anybody,
 * and the same on resume) fails that submission only, naming the file and its size, and the others
 * are graded; so do too many files and an oversized source, checked before anything is read.
 */
class SubmissionLimitsTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aThreeGigabyteClassFailsItsOwnSubmissionOnly() throws IOException {
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("alice"));
        Files.copy(Path.of("src", "test", "resources", "grade", "alice", "Explorer.java"),
                subs.resolve("alice").resolve("Explorer.java"));
        Path mallory = Files.createDirectories(subs.resolve("mallory"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", mallory.toString(), subs.resolve("alice").resolve("Explorer.java").toString()));
        Path big = mallory.resolve("Big.class");
        try {
            try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
                f.setLength(3L << 30); // sparse: no disk used
            }
            ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("lab"), 1, 1, dir.resolve("out"),
                    GradePlan.Shard.ALL, 128, 60, 5, 2.0, false, new PrintStream(OutputStream.nullOutputStream()), false,
                    false, false));
            RunRecord a = report.runs().get(0);
            RunRecord m = report.runs().get(1);
            assertEquals("alice", a.student());
            assertEquals(RunStatus.OK, a.status(), a.toString());
            assertEquals(RunStatus.COMPILE_FAILED, m.status(), m.toString());
            assertEquals("Big.class is 3.0 GiB, over the limit of 4.0 MiB for a class file; a controller's files are a few"
                    + " KB: hand in its own sources or classes only", m.detail());
        } finally {
            Files.deleteIfExists(big);
        }
    }

    @Test
    void tooManyFilesOrAnOversizedSourceAreRefusedBeforeAnythingIsRead() throws IOException {
        Path many = Files.createDirectories(dir.resolve("many"));
        for (int i = 0; i <= 5000; i++) {
            Files.createFile(many.resolve("n" + i + ".txt"));
        }
        Submission s = Submissions.prepare(many, dir.resolve("work-many"));
        assertEquals("the folder holds more than 5000 files and folders; hand in the controller's .java files (or its"
                + " .class files) alone", s.problem());

        Path huge = Files.createDirectories(dir.resolve("huge").resolve("src"));
        try (RandomAccessFile f = new RandomAccessFile(huge.resolve("Huge.java").toFile(), "rw")) {
            f.setLength(2L << 20);
        }
        Submission h = Submissions.prepare(huge.getParent(), dir.resolve("work-huge"));
        assertEquals("src/Huge.java is 2.0 MiB, over the limit of 1.0 MiB for a .java source; a controller's files are a"
                + " few KB: hand in its own sources or classes only", h.problem());
        assertTrue(!Files.exists(dir.resolve("work-huge").resolve("classes")), "nothing was compiled");
    }
}
