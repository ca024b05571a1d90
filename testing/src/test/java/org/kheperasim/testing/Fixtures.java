package org.kheperasim.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** What the tests share: the test arenas, and the line of a fixture controller's source a comment marks. */
final class Fixtures {
    private Fixtures() {
    }

    /** @return the repository's root folder */
    static Path repoRoot() {
        return Path.of(System.getProperty("kheperasim.repoRoot", "..")).toAbsolutePath().normalize();
    }

    /** @param name a test resource @return its file */
    static Path resource(String name) {
        try {
            return Path.of(Fixtures.class.getResource("/" + name).toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * @param controller a fixture controller's simple name (package {@code student})
     * @param marker a comment on one of its lines
     * @return {@code Name.java:N} for that line
     */
    static String line(String controller, String marker) {
        Path source = repoRoot().resolve("testing/src/test/java/student/" + controller + ".java");
        try {
            List<String> lines = Files.readAllLines(source);
            for (int i = 0; i < lines.size(); i++) {
                if (lines.get(i).contains(marker)) {
                    return controller + ".java:" + (i + 1);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        throw new IllegalStateException("no line of " + source + " has '" + marker + "'");
    }
}
