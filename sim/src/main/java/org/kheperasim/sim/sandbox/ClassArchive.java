package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * The simulator's class-data archive (AppCDS): the classes a run loads, parsed and verified once, in
 * a file the JVM maps at start instead ({@code -XX:SharedArchiveFile}), beside the runnable jar as
 * {@code khepera-sim.jsa}. The build makes it ({@link #main}: a short run and a short grading list
 * the classes, then {@code java -Xshare:dump} writes them); the JVMs the simulator starts are given it
 * ({@link #jvmOptions()}: grade's runs and workers, {@code run --sandbox}), and {@code java -jar}
 * itself starts warm through {@code cli.WarmStart}. A static archive, not a dynamic one
 * ({@code -XX:ArchiveClassesAtExit}): only a static archive of JDK 17 holds picocli's classes (class
 * files of Java 5), which are a fifth of the classes a run loads.
 *
 * <p>An archive is only used when it fits ({@link #fits}): made from this jar, at this path, as it is
 * now, by this JVM build, as the file beside it ({@link #key}) says and the archive's header confirms.
 * Should the JVM refuse it all the same, it runs without, silently. {@code -Dkheperasim.cds=off} or the environment's
 * {@code KHEPERASIM_CDS=off} turns it off; {@code -Dkheperasim.cds=FILE} names another archive.
 * Documented in {@code docs/startup.md}.
 */
public final class ClassArchive {
    /** The system property that turns the archive off ({@code off}) or names one. */
    public static final String PROPERTY = "kheperasim.cds";
    /** The environment variable that turns the archive off ({@code off}). */
    public static final String ENV = "KHEPERASIM_CDS";
    /** The command the build trains the archive with: what a cold run loads. */
    static final List<String> TRAINING = List.of("run", "--arena", "maze", "--controller", "WallFollower",
            "--seed", "1", "--seconds", "60");
    /** Static archives of JDK 17 begin with this, little-endian (HotSpot's CDS_ARCHIVE_MAGIC). */
    private static final int MAGIC = 0xf00baba2;
    private static final int HEADER_BYTES = 4096;

    private static volatile Optional<Path> own;

    private ClassArchive() {
    }

    /** @return false when the user turned the archive off */
    public static boolean wanted() {
        return !"off".equalsIgnoreCase(System.getProperty(PROPERTY, "")) && !"off".equalsIgnoreCase(System.getenv(ENV));
    }

    /** @return the archive this JVM's own jar has, when it fits (looked for once) */
    public static Optional<Path> current() {
        Optional<Path> a = own;
        if (a == null) {
            a = look();
            own = a;
        }
        return a;
    }

    private static Optional<Path> look() {
        if (!wanted()) {
            return Optional.empty();
        }
        List<Path> cp = OwnClasspath.entries();
        if (cp.size() != 1 || !cp.get(0).getFileName().toString().endsWith(".jar")) {
            return Optional.empty(); // classes from folders (the tests, an IDE): nothing to archive
        }
        Path jar = cp.get(0);
        String named = System.getProperty(PROPERTY, "");
        Path archive = named.isEmpty() ? beside(jar) : Path.of(named).toAbsolutePath();
        return fits(archive, jar) ? Optional.of(archive) : Optional.empty();
    }

    /**
     * @param jar the runnable jar
     * @return where its archive is: beside it, {@code khepera-sim.jar} has {@code khepera-sim.jsa}
     */
    public static Path beside(Path jar) {
        String name = jar.getFileName().toString();
        return jar.resolveSibling((name.endsWith(".jar") ? name.substring(0, name.length() - 4) : name).concat(".jsa"));
    }

    /**
     * @param archive an archive
     * @return the file beside it that says what it was made for ({@link #madeFor})
     */
    public static Path key(Path archive) {
        return archive.resolveSibling(archive.getFileName().toString().concat(".for"));
    }

    /**
     * @param jar the jar, at its real path
     * @return what an archive of this jar is made for, as its {@link #key} file holds it: the jar's real
     *     path, size and time (the JVM refuses an archive whose jar differs in any of them, and then runs
     *     with no archive at all), and the JVM build
     * @throws IOException if the jar cannot be read
     */
    static String madeFor(Path jar) throws IOException {
        return new StringBuilder().append(jar).append('\n').append(Files.size(jar)).append('\n')
                .append(Files.getLastModifiedTime(jar).toMillis()).append('\n')
                .append(System.getProperty("java.home")).append('\n')
                .append(System.getProperty("java.vm.version")).append('\n').toString();
    }

    /**
     * Cheap checks that save a JVM from being handed an archive it would refuse (it would then run
     * with no archive at all, not even the JDK's own, and slower than without): the archive's
     * {@link #key} names this jar as it is now and this JVM build, and the file begins as a static
     * archive of this JVM build does.
     *
     * @param archive the archive
     * @param jar     the jar it is for, at its real path
     * @return true when the archive is worth handing a JVM
     */
    public static boolean fits(Path archive, Path jar) {
        try {
            if (!Files.isRegularFile(archive) || !Files.isRegularFile(key(archive))
                    || !Files.readString(key(archive), StandardCharsets.UTF_8).equals(madeFor(jar))) {
                return false;
            }
            byte[] head;
            try (InputStream in = Files.newInputStream(archive)) {
                head = in.readNBytes(HEADER_BYTES);
            }
            return head.length == HEADER_BYTES && littleEndianInt(head) == MAGIC
                    && contains(head, "(".concat(System.getProperty("java.vm.version")).concat(")")
                    .getBytes(StandardCharsets.US_ASCII));
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    private static int littleEndianInt(byte[] b) {
        return (b[0] & 0xff) | (b[1] & 0xff) << 8 | (b[2] & 0xff) << 16 | (b[3] & 0xff) << 24;
    }

    private static boolean contains(byte[] in, byte[] part) {
        outer:
        for (int i = 0; i + part.length <= in.length; i++) {
            for (int j = 0; j < part.length; j++) {
                if (in[i + j] != part[j]) {
                    continue outer;
                }
            }
            return true;
        }
        return false;
    }

    /** @return the options that give a JVM started from this one's jar the archive: none without one */
    public static List<String> jvmOptions() {
        Optional<Path> a = current();
        return a.isPresent() ? jvmOptions(a.get()) : List.of();
    }

    /**
     * @param archive the archive
     * @return the options that give a JVM this archive; should it not fit after all, the JVM says nothing
     */
    public static List<String> jvmOptions(Path archive) {
        // concat, not +: this runs before the warm JVM starts, where a string-concatenation bootstrap costs
        return List.of("-XX:SharedArchiveFile=".concat(archive.toString()), "-Xshare:auto", "-Xlog:cds=off",
                "-Xlog:cds+dynamic=off");
    }

    /** The submission the build grades to train the archive: a controller of a few lines. */
    private static final String TRAINER = """
            import org.kheperasim.api.*;

            /** Drives ahead, turns on the spot when something is near in front. */
            public class Trainer extends Controller {
                @Override
                protected void doWork() {
                    boolean near = Math.max(proximity(IrSensor.FRONT_LEFT), proximity(IrSensor.FRONT_RIGHT)) > 500;
                    setSpeeds(near ? 3 : 5, near ? -3 : 5);
                    sleepMillis(100);
                }
            }
            """;

    /**
     * Makes the archive of a runnable jar, beside it: the build's last step. Two trainings list the
     * classes they load: a run ({@link #TRAINING}) as {@code java -jar ... run} runs it, and a grading
     * of one small submission (the grader's JVM and the graded one); then {@code java -Xshare:dump}
     * archives them all. Should the run or the dump fail, it says so and leaves no archive: the jar runs
     * as well without one. Should the grading fail, the archive holds the run's classes only.
     *
     * @param args the jar
     * @throws Exception if the JVMs cannot be started
     */
    public static void main(String[] args) throws Exception {
        Path jar = Path.of(args[0]).toRealPath();
        Path archive = beside(jar);
        Files.deleteIfExists(key(archive));
        Files.deleteIfExists(archive);
        Path work = archive.resolveSibling(archive.getFileName() + ".training");
        deleteTree(work);
        Files.createDirectories(work.resolve("subs").resolve("trainer"));
        Path made = archive.resolveSibling(archive.getFileName() + ".tmp");
        Path log = archive.resolveSibling(archive.getFileName() + ".log");
        Files.deleteIfExists(log);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // Both as the warm JVM runs them (cli.WarmStart), so that what it alone loads is archived too.
        List<String> jvm = List.of(java, "-D" + PROPERTY + "=off", "-Dkheperasim.cds.started=true",
                "-Djava.awt.headless=true", "-cp", jar.toString(), "org.kheperasim.sim.cli.Main");
        List<String> run = new ArrayList<>(jvm);
        run.add(1, "-XX:DumpLoadedClassList=" + work.resolve("1-run.classlist"));
        run.addAll(TRAINING);
        run.addAll(List.of("--trace", work.resolve("run.trace").toString())); // its writer's classes too
        AtomicFiles.write(work.resolve("subs").resolve("trainer").resolve("Trainer.java"), TRAINER);
        List<String> grade = new ArrayList<>(jvm);
        grade.addAll(List.of("grade", "--submissions", work.resolve("subs").toString(), "--arenas", "lab", "--seeds",
                "1", "--seconds", "5", "--heap-mb", "128", "--no-sandbox", "--out", work.resolve("grades").toString()));
        try {
            int trained = exec(run, log, Map.of());
            if (trained == 0 && exec(grade, log, Map.of("JAVA_TOOL_OPTIONS",
                    "-XX:DumpLoadedClassList=" + work.resolve("2-grade%p.classlist"))) != 0) {
                System.err.println("khepera-sim: the class-data archive holds a run's classes only (the training"
                        + " grading failed, see " + log + ")");
            }
            Path list = work.resolve("all.classlist");
            AtomicFiles.write(list, merged(work));
            int dumped = trained == 0 ? exec(List.of(java, "-Xshare:dump", "-XX:SharedClassListFile=" + list,
                    "-XX:SharedArchiveFile=" + made, "-cp", jar.toString()), log, Map.of()) : -1;
            if (dumped != 0 || !Files.isRegularFile(made)) {
                System.err.println("khepera-sim: no class-data archive was made (" + (trained != 0 ? "the training run"
                        : "java -Xshare:dump") + " failed, see " + log + "); the jar runs as well without it");
                return;
            }
            AtomicFiles.rename(made, archive);
            AtomicFiles.write(key(archive), madeFor(jar));
        } finally {
            deleteTree(work);
            Files.deleteIfExists(made);
        }
    }

    /** @return the trainings' class lists as one, in their order, each line once */
    private static String merged(Path work) throws IOException {
        LinkedHashSet<String> lines = new LinkedHashSet<>();
        try (Stream<Path> lists = Files.list(work)) {
            for (Path l : lists.filter(p -> p.toString().endsWith(".classlist")).sorted().toList()) {
                lines.addAll(Files.readAllLines(l, StandardCharsets.UTF_8));
            }
        }
        return String.join("\n", lines) + "\n";
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> all = Files.walk(dir)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    private static int exec(List<String> cmd, Path log, Map<String, String> env)
            throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        pb.environment().putAll(env);
        return pb.start().waitFor();
    }
}
