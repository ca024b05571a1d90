package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;

/**
 * The Slurm recipe of docs/grading.md, for real: the job-array script is taken from the page,
 * submitted as a 2-task array to a private single-node Slurm cluster the test starts, with the
 * merge as a dependent job; the merged report equals one unsharded grading byte for byte. Skipped
 * without slurm-wlm (and root); when CI=true it must run.
 */
class SlurmGradeTest {
    private static final Path REPO = Path.of(System.getProperty("kheperasim.repoRoot", ".."));

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theDocumentedJobArrayMakesTheSameReportAsOneGrading() throws Exception {
        Optional<String> missing = SlurmCluster.missing();
        if (missing.isPresent()) {
            if ("true".equals(System.getenv("CI"))) {
                fail(missing.get() + ", and CI=true requires the Slurm test to run");
            }
            Assumptions.assumeTrue(false, missing.get() + "; Slurm job-array test skipped");
        }
        Path subs = dir.resolve("hand-ins");
        for (String s : List.of("alice", "bob", "erin", "frank")) {
            Path to = Files.createDirectories(subs.resolve(s));
            try (Stream<Path> files = Files.list(Path.of("src/test/resources/grade", s))) {
                for (Path f : files.toList()) {
                    Files.copy(f, to.resolve(f.getFileName()));
                }
            }
        }
        // The maze with a short time limit, so each run takes a moment.
        Path arena = dir.resolve("maze20.arena");
        Files.writeString(arena, ArenaFormat.write(ArenaFormat.loadBundled("maze")).replace("time-limit 600", "time-limit 20"));
        Path script = dir.resolve("grade-array.sbatch");
        Files.writeString(script, documentedScript());
        String sim = Path.of(System.getProperty("java.home"), "bin", "java") + " -cp " + System.getProperty("java.class.path")
                + " org.kheperasim.sim.cli.Main";
        Path grades = dir.resolve("grades");

        // The unsharded grading the merged report must equal, made beside the cluster (which mostly waits on its daemons
        // and its scheduler), in a JVM of its own.
        Path whole = dir.resolve("whole");
        try (ChildGrading reference = ChildGrading.start(dir.resolve("whole.out"), "--submissions", subs.toString(), "--arenas",
                arena.toString(), "--seeds", "1", "--out", whole.toString(), "--jobs", "2");
                SlurmCluster cluster = SlurmCluster.start(dir.resolve("slurm"))) {
            String array = cluster.run(List.of("sbatch", "--parsable", "--array=1-2", "--cpus-per-task=1", "--mem=700M",
                    "--chdir=" + dir, "--output=" + dir.resolve("grade-%A_%a.log"),
                    "--export=ALL,SIM=" + sim + ",SUBMISSIONS=" + subs + ",ARENAS=" + arena + ",SEEDS=1,OUT=" + grades,
                    script.toString())).strip();
            String merge = cluster.run(List.of("sbatch", "--parsable", "--dependency=afterok:" + array, "--mem=400M",
                    "--chdir=" + dir, "--output=" + dir.resolve("merge-%j.log"),
                    "--wrap", sim + " grade merge --out " + grades.resolve("report") + " " + grades + "/shard-*")).strip();
            cluster.await(array + "," + merge, 240);
            reference.await(240);
        }
        Path merged = grades.resolve("report");
        assertTrue(Files.isRegularFile(merged.resolve("results.json")), "the merge job made no report; logs: " + logs());
        assertEquals("1/2", ReportFiles.read(grades.resolve("shard-1/results.json")).shard().toString());
        assertEquals("2/2", ReportFiles.read(grades.resolve("shard-2/results.json")).shard().toString());

        List<String> files = ReportFolder.files(whole);
        assertEquals(files, ReportFolder.files(merged));
        assertEquals(4, ReportFiles.read(merged.resolve("results.json")).runs().size());
        for (String f : files) {
            assertArrayEquals(Files.readAllBytes(whole.resolve(f)), Files.readAllBytes(merged.resolve(f)), f);
        }
    }

    /** The job-array script exactly as docs/grading.md gives it. */
    private static String documentedScript() throws IOException {
        String page = Files.readString(REPO.resolve("docs/grading.md"));
        Matcher m = Pattern.compile("```bash\n(#!/bin/bash\n#SBATCH --job-name=grade.*?)```", Pattern.DOTALL).matcher(page);
        assertTrue(m.find(), "docs/grading.md has no job-array script");
        return m.group(1);
    }

    private String logs() throws IOException {
        StringBuilder sb = new StringBuilder();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.filter(p -> p.toString().endsWith(".log")).sorted().toList()) {
                sb.append("\n== ").append(p.getFileName()).append('\n').append(Files.readString(p));
            }
        }
        return sb.toString();
    }

}
