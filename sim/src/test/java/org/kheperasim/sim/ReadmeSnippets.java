package org.kheperasim.sim;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The code a newcomer copies out of the README, read from the README itself. */
public final class ReadmeSnippets {
    private ReadmeSnippets() {
    }

    /** @return the repository's root, as the build gives it to the tests */
    public static Path root() {
        return Path.of(System.getProperty("kheperasim.repoRoot", ".."));
    }

    /**
     * @return the README's first controller ({@code MyFirst}), as a student would paste it into
     *     {@code MyFirst.java}
     * @throws IllegalStateException when the README no longer shows it
     */
    public static String firstController() throws IOException {
        String readme = Files.readString(root().resolve("README.md"));
        Matcher m = Pattern.compile("```java\\n(.*?public class MyFirst extends Controller.*?)```", Pattern.DOTALL)
                .matcher(readme);
        if (!m.find()) {
            throw new IllegalStateException("README.md no longer shows MyFirst in a java block");
        }
        return m.group(1).lines().map(l -> l.startsWith("   ") ? l.substring(3) : l).reduce("", (a, b) -> a + b + "\n");
    }
}
