package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.host.loading.ControllerPolicyError;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.ControllerCompiler;

/**
 * Finds the submissions in a folder (one sub-folder per student) and makes each runnable: its
 * {@code .java} files are compiled together with the JDK's compiler against the simulator's API;
 * a folder of {@code .class} files (in package folders) is used as it is. The controller is the
 * class that the simulator accepts as one (an Appendix {@code Thread} subclass, a {@code Controller},
 * a {@code StepController} or a WSU {@code RobotController}); classes are only loaded here, never
 * initialised, so no student code runs in the grading process. A folder past a limit on what a hand-in
 * holds ({@link SubmissionLimits}) is refused before any of it is read, and whatever goes wrong while one
 * submission is prepared is that submission's failure, with its reason.
 */
public final class Submissions {
    private Submissions() {
    }

    /**
     * @param folder the submissions folder
     * @return the student folders, sorted by name
     * @throws IllegalArgumentException if the folder does not exist or holds no sub-folder
     */
    public static List<Path> folders(Path folder) {
        if (!Files.isDirectory(folder)) {
            throw new IllegalArgumentException("--submissions " + folder + ": no such folder; give the folder that"
                    + " holds one sub-folder per student");
        }
        try (Stream<Path> s = Files.list(folder)) {
            List<Path> out = s.filter(Files::isDirectory).filter(p -> !p.getFileName().toString().startsWith("."))
                    .sorted().toList();
            if (out.isEmpty()) {
                throw new IllegalArgumentException("--submissions " + folder
                        + " holds no sub-folder; put each student's"
                        + " .java or .class files in a folder of their own (e.g. " + folder.resolve("alice") + ")");
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list " + folder + ": " + e.getMessage(), e);
        }
    }

    /**
     * Compiles (if need be) one student's folder and finds its controller.
     *
     * @param folder the student's folder
     * @param work   a folder of the student's own for compiled classes
     * @return the submission; {@link Submission#problem()} says why it cannot run, if it cannot
     */
    public static Submission prepare(Path folder, Path work) {
        String student = folder.getFileName().toString();
        try {
            String over = SubmissionLimits.check(folder);
            if (over != null) {
                return new Submission(student, null, null, over);
            }
            List<Path> sources = files(folder, ".java");
            Path classes = folder;
            if (!sources.isEmpty()) {
                classes = work.resolve("classes");
                deleteTree(classes); // no class left over from an earlier grading into the same folder
                ControllerCompiler.Result r = ControllerCompiler.compileAll(sources, classes);
                if (!r.success()) {
                    String first = r.problems().stream().filter(ControllerCompiler.Problem::error).findFirst()
                            .map(p -> p.format("?")).orElse("the compiler failed");
                    return new Submission(student, null, null, first);
                }
            } else if (files(folder, ".class").isEmpty()) {
                return new Submission(student, null, null, handedIn(folder), true);
            }
            return withController(student, classes.toAbsolutePath());
        } catch (IOException | UncheckedIOException e) {
            return new Submission(student, null, null, "cannot read the submission: " + e.getMessage());
        } catch (RuntimeException | LinkageError | OutOfMemoryError | StackOverflowError e) {
            // Whatever one hand-in does to the compiler or the class reader is its own failure, never the class's.
            return new Submission(student, null, null, "the submission could not be prepared: " + e);
        }
    }

    private static Submission withController(String student, Path classes) throws IOException {
        List<String> found = new ArrayList<>();
        for (Path f : files(classes, ".class")) {
            String rel = classes.relativize(f).toString().replace('\\', '/');
            if (rel.contains("$") || rel.endsWith("package-info.class") || rel.endsWith("module-info.class")) {
                continue;
            }
            String name = rel.substring(0, rel.length() - ".class".length()).replace('/', '.');
            try {
                new ControllerCatalog(List.of(classes)).load(name);
                found.add(name);
            } catch (ControllerException e) {
                if (e.getCause() instanceof ControllerPolicyError) {
                    found.add(name); // a controller that breaks a rule: its run says so
                }
            } catch (LinkageError | RuntimeException e) {
                // not a loadable class: not the controller
            }
        }
        if (found.isEmpty()) {
            return new Submission(student, classes, null,
                    "no controller class: none of the classes extends Thread with a"
                    + " (CurrentRobotState, MessagePasser) constructor, Controller, StepController or RobotController");
        }
        return new Submission(student, classes, found.get(0), null);
    }

    /**
     * What a folder without code holds, by name (a zip or a report handed in instead?), without the
     * folder's path: the report is the same wherever the submissions lie.
     */
    private static String handedIn(Path folder) throws IOException {
        List<String> names = files(folder, "").stream().map(p -> folder.relativize(p).toString().replace('\\', '/'))
                .filter(n -> !n.startsWith(".") && !n.contains("/.")).toList();
        if (names.isEmpty()) {
            return "the folder is empty";
        }
        String shown = String.join(", ", names.subList(0, StrictMath.min(5, names.size())))
                + (names.size() > 5 ? ", ..." : "");
        return "no .java or .class file; the folder holds "
                + (names.size() == 1 ? "1 file: " : names.size() + " files: ")
                + shown;
    }

    private static void deleteTree(Path folder) throws IOException {
        if (!Files.exists(folder)) {
            return;
        }
        try (Stream<Path> s = Files.walk(folder)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    private static List<Path> files(Path folder, String suffix) throws IOException {
        try (Stream<Path> s = Files.walk(folder, 16)) {
            return s.filter(Files::isRegularFile).filter(p -> p.getFileName().toString().endsWith(suffix))
                    .sorted().toList();
        }
    }
}
