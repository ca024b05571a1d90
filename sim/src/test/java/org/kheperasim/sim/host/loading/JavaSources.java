package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.kheperasim.api.Controller;

/** Compiles controller sources at test time, against the student API, as a student would. */
final class JavaSources {
    private JavaSources() {
    }

    /**
     * @param outputDirectory where the class files go
     * @param sources source text by binary class name (such as {@code "pkg.Robot"})
     * @return {@code outputDirectory}
     */
    static Path compile(Path outputDirectory, Map<String, String> sources) {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        List<JavaFileObject> units = new ArrayList<>();
        sources.forEach((name, text) -> units.add(new Source(name, text)));
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        List<String> options = List.of("--release", "17", "-proc:none", "-d", outputDirectory.toString(),
                "-classpath", apiClasses().toString());
        try (StandardJavaFileManager files = compiler.getStandardFileManager(diagnostics, null, null)) {
            boolean ok = compiler.getTask(null, files, diagnostics, options, null, units).call();
            assertTrue(ok, () -> "compilation failed: " + diagnostics.getDiagnostics());
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        return outputDirectory;
    }

    /** @return the directory or jar holding the student API */
    private static Path apiClasses() {
        try {
            return Path.of(Controller.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private static final class Source extends SimpleJavaFileObject {
        private final String text;

        Source(String className, String text) {
            super(URI.create("string:///" + className.replace('.', '/') + Kind.SOURCE.extension), Kind.SOURCE);
            this.text = text;
        }

        @Override
        public CharSequence getCharContent(boolean ignoreEncodingErrors) {
            return text;
        }
    }
}
