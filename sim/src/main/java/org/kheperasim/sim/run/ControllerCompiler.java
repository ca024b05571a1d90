package org.kheperasim.sim.run;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.kheperasim.api.Controller;

/**
 * Compiles a student's controller source ({@code Robot.java}) with the JDK's compiler against the
 * simulator's API, so the window can run a {@code .java} file directly. Errors come back with
 * their line numbers; the class is then loaded through a {@link ControllerCatalog} on the output
 * folder (a fresh class loader each time, so a recompiled class is picked up).
 */
public final class ControllerCompiler {
    private static final System.Logger LOG = System.getLogger(ControllerCompiler.class.getName());

    private static final Pattern PACKAGE = Pattern.compile("^\\s*package\\s+([\\w.]+)\\s*;", Pattern.MULTILINE);

    /**
     * One compiler message.
     *
     * @param error true for an error, false for a warning
     * @param line the line in the source, 1-based (0 when it concerns no line)
     * @param column the column, 1-based (0 when unknown)
     * @param message what the compiler said
     * @param source the file it concerns (its name), or null when the compilation had one file
     */
    public record Problem(boolean error, long line, long column, String message, String source) {
        /**
         * A problem in the one file compiled.
         *
         * @param error true for an error
         * @param line the line, 1-based (0 when none)
         * @param column the column, 1-based (0 when unknown)
         * @param message what the compiler said
         */
        public Problem(boolean error, long line, long column, String message) {
            this(error, line, column, message, null);
        }

        /**
         * @param file the source's name (used when the problem names none) @return {@code Robot.java:12:5: error: ...}
         */
        public String format(String file) {
            return (source != null ? source : file) + ":" + line + (column > 0 ? ":" + column : "") + ": "
                    + (error ? "error" : "warning") + ": " + message;
        }
    }

    /**
     * What a compilation produced.
     *
     * @param success true when it compiled
     * @param className the controller's class name (with its package, if any)
     * @param classes the folder the classes went to
     * @param problems errors and warnings, in order
     */
    public record Result(boolean success, String className, Path classes, List<Problem> problems) {
        /** Copies the list. */
        public Result {
            problems = List.copyOf(problems);
        }

        /** @param file how to name the source @return every problem, one per line */
        public String report(String file) {
            StringBuilder sb = new StringBuilder();
            for (Problem p : problems) {
                sb.append(p.format(file)).append('\n');
            }
            return sb.toString();
        }
    }

    private ControllerCompiler() {
    }

    /**
     * Compile one source file.
     *
     * @param source the {@code .java} file
     * @param classes the folder the classes go to (created)
     * @return the result, with the compiler's messages
     * @throws IllegalStateException if this Java has no compiler (a JRE rather than a JDK)
     * @throws IOException if the source cannot be read
     */
    public static Result compile(Path source, Path classes) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IllegalStateException("this Java runtime has no compiler (it is a JRE, not a JDK); run the"
                    + " simulator with a JDK 17+, or compile yourself: javac -cp khepera-sim.jar -d out "
                    + source.getFileName());
        }
        String text = Files.readString(source, StandardCharsets.UTF_8);
        String simple = source.getFileName().toString().replaceFirst("\\.java$", "");
        Matcher m = PACKAGE.matcher(text);
        String pkg = m.find() ? m.group(1) : null;
        String className = pkg != null ? pkg + "." + simple : simple;
        Path folder = source.toAbsolutePath().getParent();
        Path root = folder;
        for (int i = 0; pkg != null && i <= pkg.length() - pkg.replace(".", "").length() && root != null; i++) {
            root = root.getParent();
        }
        // With the other .java files of its folder, as grade compiles a hand-in; classes of other folders
        // (packaged helpers) are found through the source path as they are named.
        List<Path> together = new ArrayList<>(List.of(source));
        try (java.util.stream.Stream<Path> list = Files.list(folder)) {
            list.filter(p -> p.toString().endsWith(".java") && Files.isRegularFile(p))
                    .filter(p -> !p.toAbsolutePath().equals(source.toAbsolutePath())).sorted().forEach(together::add);
        }
        List<String> sourcepath = root == null ? List.of() : List.of("-sourcepath", root.toString());
        Result r = compileAll(javac, together, classes, false, sourcepath);
        if (!r.success() && together.size() > 1 && r.problems().stream()
                .noneMatch(p -> p.error()
                        && (p.source() == null || p.source().equals(source.getFileName().toString())))) {
            // Only files it does not use failed: the controller alone, with what it names from the folder.
            r = compileAll(javac, List.of(source), classes, false, sourcepath);
        }
        if (!r.success() && pkg == null && !MissingImports.apiClasses(r.problems()).isEmpty()) {
            Result imported = compileWithApiImport(javac, source, text, together, classes, sourcepath);
            if (imported.success()) {
                List<Problem> problems = new ArrayList<>(List.of(new Problem(false, 1, 0, "it names the API's classes ("
                        + String.join(", ", MissingImports.apiClasses(r.problems()))
                        + ") without importing them: compiled as"
                        + " if its first line were `" + MissingImports.API_IMPORT + "`; add that line")));
                problems.addAll(imported.problems());
                return new Result(true, className, classes, problems);
            }
        }
        return new Result(r.success(), className, classes, MissingImports.annotate(r.problems()));
    }

    /** The default-package source compiled as if its first line imported the API (the original compiled beside it). */
    private static Result compileWithApiImport(JavaCompiler javac, Path source, String text, List<Path> together,
            Path classes, List<String> sourcepath) throws IOException {
        Path copyDir = Files.createTempDirectory("khepera-import");
        try {
            Path copy = copyDir.resolve(source.getFileName().toString());
            org.kheperasim.sim.files.AtomicFiles.write(copy, MissingImports.withApiImport(text));
            List<Path> files = new ArrayList<>(together);
            files.set(0, copy);
            return compileAll(javac, files, classes, false, sourcepath);
        } finally {
            try (java.util.stream.Stream<Path> left = Files.list(copyDir)) {
                for (Path p : left.toList()) {
                    Files.deleteIfExists(p);
                }
            }
            Files.deleteIfExists(copyDir);
        }
    }

    /**
     * Compile several source files together (a submission with helper classes), e.g. for grading.
     *
     * @param sources the {@code .java} files
     * @param classes the folder the classes go to (created)
     * @return the result, with each problem naming its file; its class name is null (a caller that
     *     needs the controller looks through the classes)
     * @throws IllegalStateException if this Java has no compiler (a JRE rather than a JDK)
     * @throws IOException if the output folder cannot be made
     */
    public static Result compileAll(List<Path> sources, Path classes) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IllegalStateException(
                    "this Java runtime has no compiler (it is a JRE, not a JDK); grade with a JDK 17+");
        }
        return compileAll(javac, sources, classes, true, List.of());
    }

    private static Result compileAll(JavaCompiler javac, List<Path> sources, Path classes, boolean nameFiles,
            List<String> extraOptions) throws IOException {
        Files.createDirectories(classes);
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        List<String> options = new ArrayList<>(List.of("--release", "17", "-proc:none", "-g", "-d", classes.toString(),
                "-classpath", classpath()));
        options.addAll(extraOptions);
        boolean ok;
        StringWriter out = new StringWriter();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                StandardCharsets.UTF_8)) {
            ok = javac.getTask(out, files, diagnostics, options, null,
                    files.getJavaFileObjects(sources.stream().map(Path::toFile).toArray(File[]::new))).call();
        }
        List<Problem> problems = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
            if (d.getKind() == Diagnostic.Kind.NOTE) {
                continue;
            }
            String named = d.getSource() != null ? Path.of(d.getSource().toUri()).getFileName().toString() : null;
            // Naming files only when asked, or when the problem is in another file than the first given.
            String file = nameFiles
                    || named != null && !named.equals(sources.get(0).getFileName().toString()) ? named : null;
            problems.add(new Problem(d.getKind() == Diagnostic.Kind.ERROR, StrictMath.max(0, d.getLineNumber()),
                    StrictMath.max(0, d.getColumnNumber()), d.getMessage(Locale.ROOT), file));
        }
        if (!ok && problems.isEmpty()) {
            problems.add(new Problem(true, 0, 0, out.toString().strip()));
        }
        return new Result(ok, null, classes, problems);
    }

    /** The API classes, and whatever this application runs from (the jar, or target/classes). */
    static String classpath() {
        Set<String> entries = new LinkedHashSet<>();
        try {
            entries.add(Path.of(
                    Controller.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        } catch (URISyntaxException | RuntimeException e) {
            // Fall back to java.class.path below.
            LOG.log(System.Logger.Level.DEBUG, "cannot locate the API classes' jar, using java.class.path: " + e);
        }
        for (String e : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (!e.isBlank()) {
                entries.add(e);
            }
        }
        return String.join(File.pathSeparator, entries);
    }
}
