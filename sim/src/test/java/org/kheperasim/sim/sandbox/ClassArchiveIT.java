package org.kheperasim.sim.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The runnable jar's class-data archive ({@code target/khepera-sim.jsa}, made by {@code package}),
 * as a user meets it: {@code java -jar khepera-sim.jar run} starts warm and its trace and output are
 * those of a cold start, byte for byte; an archive that does not fit (a copy made for another jar, a
 * truncated one, garbage) changes nothing and is not mentioned; grade starts warm and its JVMs are
 * given it, and without it (or with {@code KHEPERASIM_CDS=off}) are not.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ClassArchiveIT {
    private static final Path JAR = Path.of("target", "khepera-sim.jar").toAbsolutePath();
    private static final List<String> RUN = List.of("run", "--arena", "maze", "--controller", "WallFollower", "--seed",
            "3", "--seconds", "20");

    @TempDir
    Path dir;

    @Test
    void aWarmRunWritesTheTraceAndPrintsTheOutputOfAColdOne() throws Exception {
        requireArchive();
        Ran warm = java(JAR, List.of(), Map.of(), "warm.trace");
        Ran cold = java(JAR, List.of(), Map.of(ClassArchive.ENV, "off"), "cold.trace");
        assertEquals(0, warm.exit, warm.err);
        assertEquals(0, cold.exit, cold.err);
        assertEquals("", warm.err);
        assertEquals("", cold.err);
        assertEquals(timeless(cold.out), timeless(warm.out));
        assertTrue(Arrays.equals(Files.readAllBytes(dir.resolve("cold.trace")),
                Files.readAllBytes(dir.resolve("warm.trace"))), "the traces are byte-identical");

        // It did start warm: the command's classes came from the archive (the option is passed on).
        Ran seen = java(JAR, List.of("-verbose:class"), Map.of(), "seen.trace");
        assertTrue(seen.out.contains("org.kheperasim.sim.cli.RunCommand source: shared objects file"), seen.out);
        Ran off = java(JAR, List.of("-verbose:class"), Map.of(ClassArchive.ENV, "off"), "off.trace");
        assertFalse(off.out.contains("org.kheperasim.sim.cli.RunCommand source: shared objects file"), off.out);
    }

    @Test
    void aSigtermToTheJvmStartedStopsTheWarmRunAsItStopsAColdOne() throws Exception {
        requireArchive();
        for (Map<String, String> env : List.of(Map.<String, String>of(), Map.of(ClassArchive.ENV, "off"))) {
            Path trace = dir.resolve("long.trace");
            Files.deleteIfExists(trace);
            List<String> cmd = new ArrayList<>(List.of(java(), "-jar", JAR.toString(), "run", "--arena", "maze",
                    "--controller", "WallFollower", "--seed", "1", "--seconds", "100000", "--trace", trace.toString()));
            ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(dir.resolve("long.out").toFile())
                    .redirectError(dir.resolve("long.err").toFile());
            clean(pb);
            pb.environment().putAll(env);
            Process p = pb.start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while ((!Files.exists(trace) || Files.size(trace) < 10_000) && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            List<ProcessHandle> below = p.descendants().toList();
            p.destroy(); // SIGTERM to the JVM the user started, not to the one it started
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), env + ": stopped");
            assertEquals(143, p.exitValue(), env.toString());
            String err = Files.readString(dir.resolve("long.err"));
            assertTrue(err.contains("stopped at") && err.contains("because the program is being shut down"), env + err);
            assertTrue(Files.readString(dir.resolve("long.out")).contains("WallFollower in maze: "), env.toString());
            for (ProcessHandle h : below) {
                assertTrue(h.onExit().get(30, TimeUnit.SECONDS) != null && !h.isAlive(), env + ": left " + h);
            }
        }
    }

    @Test
    void killingTheJvmStartedEndsTheWarmOneToo() throws Exception {
        requireArchive();
        Path trace = dir.resolve("killed.trace");
        ProcessBuilder pb = new ProcessBuilder(java(), "-jar", JAR.toString(), "run", "--arena", "maze", "--controller",
                "WallFollower", "--seed", "1", "--seconds", "100000", "--trace", trace.toString())
                .redirectOutput(dir.resolve("killed.out").toFile()).redirectError(dir.resolve("killed.err").toFile());
        clean(pb);
        Process p = pb.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while ((!Files.exists(trace) || Files.size(trace) < 10_000) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        List<ProcessHandle> below = p.descendants().toList();
        assertFalse(below.isEmpty(), "the run started warm, in a JVM of its own");
        p.destroyForcibly(); // kill -9: nothing of the first JVM runs
        assertTrue(p.waitFor(30, TimeUnit.SECONDS));
        for (ProcessHandle h : below) {
            h.onExit().get(30, TimeUnit.SECONDS);
            assertFalse(h.isAlive(), "the warm JVM ended with it: " + h);
        }
    }

    @Test
    void anArchiveThatDoesNotFitChangesNothingAndSaysNothing() throws Exception {
        requireArchive();
        Path jar = Files.copy(JAR, Files.createDirectories(dir.resolve("copy")).resolve("khepera-sim.jar"));
        Ran reference = java(jar, List.of(), Map.of(), "reference.trace");
        assertEquals(0, reference.exit, reference.err);
        byte[] trace = Files.readAllBytes(dir.resolve("reference.trace"));
        Path archive = ClassArchive.beside(jar);
        Path real = ClassArchive.beside(JAR);
        byte[] truncated;
        try (InputStream in = Files.newInputStream(real)) {
            truncated = in.readNBytes(1 << 16);
        }
        for (String kind : List.of("made for the jar elsewhere", "truncated", "garbage")) {
            switch (kind) {
                case "made for the jar elsewhere" -> Files.copy(real, archive);
                case "truncated" -> Files.write(archive, truncated);
                default -> Files.writeString(archive, "garbage\n");
            }
            // A key that names the copy: the simulator's own checks pass, the JVM is handed the archive.
            Files.writeString(ClassArchive.key(archive), ClassArchive.madeFor(jar.toRealPath()),
                    StandardCharsets.UTF_8);
            Ran r = java(jar, List.of(), Map.of(), "run.trace");
            assertEquals(0, r.exit, kind + ": " + r.err);
            assertEquals("", r.err, kind);
            assertEquals(timeless(reference.out), timeless(r.out), kind);
            assertTrue(Arrays.equals(trace, Files.readAllBytes(dir.resolve("run.trace"))), kind + ": the same trace");
            Files.delete(archive);
            Files.delete(ClassArchive.key(archive));
        }
    }

    @Test
    void gradesJvmsAreGivenTheArchiveOnlyWhenThereIsOne() throws Exception {
        requireArchive();
        Path subs = Files.createDirectories(dir.resolve("subs").resolve("alice"));
        Files.copy(Path.of("src", "test", "resources", "grade", "alice", "Explorer.java"),
                subs.resolve("Explorer.java"));
        String flag = "-XX:SharedArchiveFile=" + ClassArchive.beside(JAR.toRealPath());
        boolean box = BoxProbe.unavailable().isEmpty();
        for (String sandbox : box ? List.of("--no-sandbox", "") : List.of("--no-sandbox")) {
            Set<String> with = grade(sandbox, Map.of(), "with" + sandbox);
            assertTrue(with.stream().anyMatch(c -> c.contains(" grade ") && c.contains(flag)),
                    "the grader itself started warm: " + with);
            assertTrue(with.stream().anyMatch(c -> !c.contains(" grade ")), "a graded JVM was seen: " + with);
            assertTrue(with.stream().allMatch(c -> c.contains(flag)), flag + " in " + with);
            Set<String> without = grade(sandbox, Map.of(ClassArchive.ENV, "off"), "without" + sandbox);
            assertTrue(without.stream().anyMatch(c -> !c.contains(" grade ")), "a graded JVM was seen: " + without);
            assertTrue(without.stream().noneMatch(c -> c.contains("SharedArchiveFile")), without.toString());
        }
    }

    /** @return the command lines of the graded JVMs seen while grade ran (each run's or a worker's) */
    private Set<String> grade(String sandbox, Map<String, String> env, String name) throws Exception {
        Path out = dir.resolve("out-" + name);
        List<String> cmd = new ArrayList<>(List.of(java(), "-jar", JAR.toString(), "grade", "--submissions",
                dir.resolve("subs").toString(), "--arenas", "lab", "--seeds", "2", "--seconds", "5",
                "--wall-limit", "60", "--heap-mb", "128", "--out", out.toString()));
        if (!sandbox.isEmpty()) {
            cmd.add(sandbox);
        }
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(dir.resolve(name + ".txt").toFile());
        clean(pb);
        pb.environment().putAll(env);
        Process p = pb.start();
        Set<String> seen = new TreeSet<>();
        while (!p.waitFor(5, TimeUnit.MILLISECONDS)) {
            p.descendants().forEach(h -> h.info().commandLine().ifPresent(c -> {
                if (c.contains("GradedRun") || c.contains("WorkerMain") || c.contains(" grade ")) {
                    seen.add(c);
                }
            }));
        }
        assertEquals(0, p.exitValue(), Files.readString(dir.resolve(name + ".txt")));
        String results = Files.readString(out.resolve("results.csv"));
        assertTrue(results.contains(",ok,") || results.contains(",ok"), results);
        return seen;
    }

    /** Without the variables that turn the archive off or that keep a second JVM from starting. */
    private static void clean(ProcessBuilder pb) {
        for (String name : List.of(ClassArchive.ENV, "JDK_JAVA_OPTIONS", "JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS")) {
            pb.environment().remove(name);
        }
    }

    private static void requireArchive() {
        assertTrue(Files.isRegularFile(JAR), "the runnable jar is built before the integration tests: " + JAR);
        Assumptions.assumeTrue(ClassArchive.fits(ClassArchive.beside(JAR), realPath(JAR)),
                "the build made no class-data archive (-Dkheperasim.cds.skip?)");
    }

    private static Path realPath(Path p) {
        try {
            return p.toRealPath();
        } catch (IOException e) {
            return p;
        }
    }

    private record Ran(int exit, String out, String err) {
    }

    private Ran java(Path jar, List<String> options, Map<String, String> env, String trace) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(java()));
        cmd.addAll(options);
        cmd.addAll(List.of("-jar", jar.toString()));
        cmd.addAll(RUN);
        cmd.addAll(List.of("--trace", dir.resolve(trace).toString()));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
        clean(pb);
        pb.environment().putAll(env);
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "ended in time");
        return new Ran(p.exitValue(), Files.readString(out), Files.readString(err));
    }

    private static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    /** The output without its one wall-clock figure ("simulated in 0.07 s (915x real time)"). */
    private static String timeless(String out) {
        return out.replaceAll("simulated in [0-9.]+ s \\([0-9.]+x real time\\)", "simulated in T");
    }
}
