package org.kheperasim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The engine knows nothing about the screen: nothing below the GUI imports AWT or Swing. */
class ArchitectureTest {
    private static final Path SRC = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("sim/src/main/java/org/kheperasim/sim");

    @Test
    void engineHostRunTraceAndArenaDoNotTouchTheScreen() throws IOException {
        List<String> offenders;
        try (Stream<Path> files = Files.walk(SRC)) {
            offenders = files.filter(p -> p.toString().endsWith(".java"))
                    .filter(p -> !SRC.relativize(p).startsWith("gui"))
                    .filter(ArchitectureTest::importsScreen)
                    .map(p -> SRC.relativize(p).toString())
                    .collect(Collectors.toList());
        }
        assertEquals(List.of(), offenders, "only the gui package may import java.awt or javax.swing");
    }

    private static boolean importsScreen(Path p) {
        try {
            String text = Files.readString(p);
            return text.contains("import java.awt") || text.contains("import javax.swing");
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
