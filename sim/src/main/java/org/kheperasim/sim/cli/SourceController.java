package org.kheperasim.sim.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.run.ControllerCompiler;

/**
 * {@code run --controller Robot.java}: the source compiled as the window compiles it (with the other
 * {@code .java} files of its folder, see {@link ControllerCompiler#compile}) into a folder of its own
 * that goes first on the classpath and is deleted when the JVM ends; any other controller name is
 * left as it is.
 */
final class SourceController {
    /** The controller to run and its classpath. */
    record Compiled(String controller, List<Path> classpath) {
    }

    private SourceController() {
    }

    /**
     * @param controller the {@code --controller} given
     * @param classpath the {@code --classpath} given
     * @param err where the compiler's messages go
     * @return the class to run and the classpath with its classes first; the arguments themselves when
     *     the controller names no {@code .java} file that exists
     * @throws ControllerException when the source does not compile: one line naming its first error
     *     (every message is printed to {@code err} before)
     */
    static Compiled of(String controller, List<Path> classpath, PrintStream err) throws IOException {
        Path source = Path.of(controller.strip());
        if (!controller.strip().endsWith(".java") || !Files.isRegularFile(source)) {
            return new Compiled(controller, classpath);
        }
        Path out = Files.createTempDirectory("khepera-run-classes");
        Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(out), "delete " + out));
        ControllerCompiler.Result r = ControllerCompiler.compile(source, out);
        String file = source.getFileName().toString();
        if (!r.problems().isEmpty()) {
            err.print(r.report(file));
        }
        if (!r.success()) {
            List<ControllerCompiler.Problem> errors =
                    r.problems().stream().filter(ControllerCompiler.Problem::error).toList();
            String first = errors.isEmpty() ? "the compiler failed"
                    : errors.get(0).format(file).lines().findFirst().orElse("");
            throw new ControllerException(file + " does not compile: " + first
                    + (errors.size() > 1 ? " (" + (errors.size() - 1) + " more errors above)" : "")
                    + "; fix it and run again");
        }
        List<Path> path = new ArrayList<>(List.of(out));
        path.addAll(classpath);
        return new Compiled(r.className(), path);
    }

    private static void delete(Path dir) {
        try (Stream<Path> all = Files.walk(dir)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            // A temporary folder left behind: nothing to tell the user at exit.
        }
    }
}
