package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.ReadmeSnippets;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * The first controllers a newcomer meets, the README's {@code MyFirst} (compiled from the README
 * itself) and the bundled {@code Template}, never end up pinned against a wall with their wheels
 * turning: over 20 seeds of two simulated minutes, no contact lasts 5 s.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class FirstControllersTest {
    private static final double PINNED_S = 5;

    @TempDir
    Path dir;

    /** @return the longest stretch the robot spent touching something, s, and the run */
    private static double[] longestContact(String arena, String controller, List<Path> classpath, long seed) {
        long[] since = {-1};
        double[] longest = {0};
        RunResult r = Simulation.builder().arena(arena).controller(controller).classpath(classpath).seed(seed).seconds(120)
                .listener(s -> {
                    RobotView v = s.robots().get(0);
                    if (v.contact() == Contact.NONE) {
                        since[0] = -1;
                    } else {
                        if (since[0] < 0) {
                            since[0] = s.timeNanos();
                        }
                        longest[0] = StrictMath.max(longest[0], (s.timeNanos() - since[0]) / 1e9);
                    }
                }, 100).run();
        return new double[] {longest[0], r.first().distanceMm()};
    }

    private static void neverPinned(String controller, List<Path> classpath, String... arenas) {
        for (String arena : arenas) {
            List<String> pinned = new ArrayList<>();
            for (long seed = 1; seed <= 20; seed++) {
                double[] c = longestContact(arena, controller, classpath, seed);
                if (c[0] >= PINNED_S) {
                    pinned.add("seed " + seed + ": " + c[0] + " s");
                }
                assertTrue(c[1] > 500, controller + " in " + arena + " seed " + seed + " drove only " + c[1] + " mm");
            }
            assertEquals(List.of(), pinned, controller + " in " + arena + " stayed against something for " + PINNED_S + " s or more");
        }
    }

    @Test
    void theTemplateIsNeverPinnedAgainstAWall() {
        neverPinned("Template", List.of(), "lab", "maze", "two-rooms");
    }

    @Test
    void theReadmesFirstControllerCompilesFromTheReadmeAndIsNeverPinned() throws IOException {
        String source = ReadmeSnippets.firstController();
        String quickStart = Files.readString(ReadmeSnippets.root().resolve("docs/quick-start.md"));
        assertTrue(quickStart.replaceAll("\\s+", " ").contains(source.replaceAll("\\s+", " ").strip()),
                "docs/quick-start.md shows the same MyFirst as the README");
        Path file = dir.resolve("MyFirst.java");
        Files.writeString(file, source);
        Path out = Files.createDirectories(dir.resolve("out"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("java.class.path"), "-d", out.toString(), file.toString()), "MyFirst compiles");
        neverPinned("MyFirst", List.of(out), "lab", "maze");
    }
}
