package org.kheperasim.sim;

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
 * Every Java snippet in README.md and docs/*.md compiles against the simulator's API, as a student
 * would compile it: each {@code ```java} block is a whole source file (sketches are fenced
 * {@code ```text}), named after its public class.
 */
class DocsSnippetsTest {
    private static final Path REPO = Path.of(System.getProperty("kheperasim.repoRoot", ".."));
    private static final Pattern BLOCK = Pattern.compile("```java\\n(.*?)```", Pattern.DOTALL);
    private static final Pattern CLASS = Pattern.compile("public\\s+(?:abstract\\s+)?class\\s+(\\w+)");

    @TempDir
    Path dir;

    @Test
    void everyJavaSnippetInTheDocsCompiles() throws IOException {
        List<Path> pages = new ArrayList<>(List.of(REPO.resolve("README.md")));
        try (Stream<Path> docs = Files.list(REPO.resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int compiled = 0;
        List<String> failures = new ArrayList<>();
        for (Path page : pages) {
            Matcher m = BLOCK.matcher(Files.readString(page));
            int n = 0;
            while (m.find()) {
                n++;
                String code = m.group(1).stripIndent();
                Matcher c = CLASS.matcher(code);
                assertTrue(c.find(), page.getFileName() + " snippet " + n + " declares no public class; fence a sketch as"
                        + " ```text, not ```java:\n" + code);
                Path src = Files.createDirectories(dir.resolve(page.getFileName() + "-" + n)).resolve(c.group(1) + ".java");
                Files.writeString(src, code);
                StringWriter out = new StringWriter();
                boolean ok = javac.getTask(out, null, null, List.of("-classpath", System.getProperty("java.class.path"), "-d",
                        src.getParent().toString(), "-Xlint:none"), null,
                        javac.getStandardFileManager(null, null, null).getJavaFileObjects(src.toFile())).call();
                if (!ok) {
                    failures.add(page.getFileName() + " snippet " + n + " (" + c.group(1) + "):\n" + out);
                }
                compiled++;
            }
        }
        assertEquals(List.of(), failures);
        assertTrue(compiled >= 5, "the docs hold at least five Java snippets; found " + compiled);
        System.out.println(compiled + " Java snippets in the docs compile");
    }
}
