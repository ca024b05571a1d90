package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every test snippet in README.md and docs/*.md compiles against the testing API, as a student's test
 * would. They are fenced {@code ```java testing} (GitHub still colours them as Java): the simulator's own
 * snippet test compiles the plain {@code ```java} blocks against the simulator alone, which has no testing
 * API. Each snippet is a whole test class; a controller {@code MyController} is there to test.
 */
class DocsTestingSnippetsTest {
    private static final Pattern BLOCK = Pattern.compile("```java testing\\n(.*?)```", Pattern.DOTALL);
    private static final Pattern CLASS = Pattern.compile("class\\s+(\\w+)");
    private static final String CONTROLLER = "public class MyController extends org.kheperasim.api.Controller {\n"
            + "    @Override\n    protected void doWork() {\n        sleepMillis(100);\n    }\n}\n";

    @Test
    void everyTestSnippetInTheDocsCompiles(@TempDir Path dir) throws IOException {
        Path repo = Fixtures.repoRoot();
        List<Path> pages = new ArrayList<>(List.of(repo.resolve("README.md")));
        try (Stream<Path> docs = Files.list(repo.resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        // One compilation for all of them (javac's start is most of the cost), each snippet in a package of its own.
        List<Path> sources = new ArrayList<>();
        int n = 0;
        for (Path page : pages) {
            Matcher m = BLOCK.matcher(Files.readString(page));
            while (m.find()) {
                n++;
                String code = m.group(1).stripIndent();
                Matcher c = CLASS.matcher(code);
                assertTrue(c.find(), page.getFileName() + " test snippet " + n + " declares no class:\n" + code);
                String pkg = "snippet" + n;
                Path src = Files.createDirectories(dir.resolve(pkg));
                sources.add(Files.writeString(src.resolve(c.group(1) + ".java"), "package " + pkg + "; // " + page.getFileName()
                        + "\n" + code));
                sources.add(Files.writeString(src.resolve("MyController.java"), "package " + pkg + ";\n" + CONTROLLER));
            }
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        StringWriter out = new StringWriter();
        boolean ok = javac.getTask(out, null, null, List.of("-classpath", System.getProperty("java.class.path"), "-d",
                dir.resolve("classes").toString(), "-Xlint:none"), null,
                javac.getStandardFileManager(null, null, null).getJavaFileObjectsFromPaths(sources)).call();
        List<String> failures = ok ? List.of() : List.of(out.toString());
        int compiled = n;
        assertEquals(List.of(), failures);
        assertTrue(compiled >= 4, "docs/testing.md and docs/autograding.md hold test snippets; found " + compiled);
    }
}
