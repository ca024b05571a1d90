package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Golden traces: every bundled arena with each demo controller, compared byte for byte with the
 * trace committed under {@code sim/src/test/resources/golden/}. A change to any model shows here as
 * a diff to review like code. Regenerate with {@code mvn -pl sim -am verify -Dgolden.update=true}.
 */
class GoldenTraceTest {
    private static final Path REPO = Path.of(System.getProperty("kheperasim.repoRoot", ".."));
    private static final Path GOLDEN = REPO.resolve("sim/src/test/resources/golden");

    static Stream<Arguments> cases() throws IOException {
        List<Arguments> out = new ArrayList<>();
        try (Stream<Path> files = Files.list(REPO.resolve("arenas"))) {
            for (Path f : files.filter(p -> p.toString().endsWith(".arena")).sorted().toList()) {
                String arena = f.getFileName().toString().replace(".arena", "");
                for (String controller : List.of("WallFollower", "Braitenberg")) {
                    out.add(Arguments.of(arena, controller));
                }
            }
        }
        return out.stream();
    }

    @ParameterizedTest(name = "{0} with {1}")
    @MethodSource("cases")
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void traceMatchesTheGoldenFile(String arena, String controller) throws IOException {
        StringWriter out = new StringWriter();
        Simulation.builder().arena(REPO.resolve("arenas/" + arena + ".arena").toString()).controller(controller)
                .seed(1).seconds(60).sampleMillis(100).trace(out).run();
        String trace = out.toString().replace(REPO.toString(), "");
        Path golden = GOLDEN.resolve(arena + "-" + controller + ".trace");
        if (Boolean.getBoolean("golden.update")) {
            Files.createDirectories(GOLDEN);
            Files.writeString(golden, trace);
            return;
        }
        assertTrue(Files.exists(golden), "no golden trace " + golden + "; create it with -Dgolden.update=true and review it");
        assertEquals(Files.readString(golden), trace, "the run no longer matches " + golden
                + "; if the change is intended, regenerate with -Dgolden.update=true and review the diff");
    }
}
