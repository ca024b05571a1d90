package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.ball;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.light;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * The WSU world file the repository ships for docs/wsu-migration.md's examples, {@code
 * docs/examples/wsu-course/lamp-gates}: written by the project's own {@link WsuWorldWriter} (a
 * course's own world files cannot be shipped), with the course-style arena file beside it and the
 * {@code Avoider} the page compiles. The page's two commands run here, and print what it shows.
 *
 * <p>Regenerate the file after changing the world below with {@code -Dwsu.examples.update=true}.
 */
class WsuExampleWorldTest {
    static final Path EXAMPLES = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("docs/examples/wsu-course");
    private static final Path PAGE = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("docs/wsu-migration.md");

    /**
     * Two rows of walls across the panel, each with a gate 50 px (122 mm) wide and a lamp at either
     * side of it, a ball between them; the robot starts at the original's spot, (263, 263) px.
     */
    static List<WsuWorldWriter.Vertex> lampGates() {
        List<WsuWorldWriter.Vertex> v = new ArrayList<>();
        int id = 5;
        for (int x : new int[] {34, 84, 134, 184, 284, 334, 384, 434}) {   // y 142..149, gate x 234..284
            v.add(horizontal(id++, x, 150));
        }
        for (int x : new int[] {20, 70, 170, 220, 270, 320, 370, 420}) {    // y 372..379, gate x 120..170
            v.add(horizontal(id++, x, 380));
        }
        v.add(light(id++, 216, 156));
        v.add(light(id++, 286, 156));
        v.add(light(id++, 102, 350));
        v.add(light(id++, 172, 350));
        v.add(ball(id++, 380, 300));
        return v;
    }

    @TempDir
    Path dir;

    @Test
    void theShippedWorldIsWhatTheWriterWrites() throws IOException {
        byte[] bytes = WsuWorldWriter.world(lampGates());
        Path shipped = EXAMPLES.resolve("lamp-gates");
        if (Boolean.getBoolean("wsu.examples.update")) {
            Files.write(shipped, bytes);
        }
        assertArrayEquals(bytes, Files.readAllBytes(shipped), "regenerate with -Dwsu.examples.update=true");
        List<String> warnings = new ArrayList<>();
        Arena a = WsuWorld.read(shipped, warnings::add);
        assertEquals(List.of(), warnings, "a clean world: nothing clipped, the start spot free");
        assertEquals(4, a.lights().size());
        assertEquals(1, a.caps().size());
    }

    @Test
    void thePagesAvoiderRunsInTheWorldAsThePageShows() throws Exception {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), EXAMPLES.resolve("Avoider.java").toString()));
        RunResult r = Simulation.builder().arena(EXAMPLES.resolve("lamp-gates").toString()).classpath(List.of(classes))
                .controller("Avoider").seconds(300).seed(1).console(l -> { }).run();
        RunResult.RobotResult f = r.first();
        String shown = String.format(Locale.ROOT, "ended at (%.1f, %.1f) mm heading %.1f deg; travelled %.2f m; %d collisions;"
                + " visited %.1f%% of the floor", f.x(), f.y(), f.headingDeg(), f.distanceMm() / 1000, f.collisions(), f.visitedPercent());
        String page = Files.readString(PAGE);
        assertTrue(page.contains(shown), "the page shows what the run prints: " + shown);
        assertTrue(f.distanceMm() > 2000, "it drives about: " + f);
    }

    @Test
    void theCourseArenaScoresTheGatesPassed() throws IOException {
        Arena a = ArenaFiles.load(EXAMPLES.resolve("lamp-gates-course.arena"));
        Arena w = WsuWorld.read(EXAMPLES.resolve("lamp-gates"), note -> { });
        assertEquals(w.walls(), a.walls());
        assertEquals(w.lights(), a.lights());
        assertEquals(List.of("gate1", "gate2"), a.regions().stream().map(g -> g.name()).toList());
        RunResult r = Simulation.builder().arena(a).controller("WallFollower").seed(1)
                .seconds(a.assignment().timeLimitSeconds()).run();
        Score s = Score.of(a, RunFacts.of(r));
        String page = Files.readString(PAGE);
        assertTrue(page.contains("score " + s.summary()), "the page shows the score the run prints: " + s.summary());
        assertEquals(100, s.percent(), 1e-9, "the wall follower passes both gates: " + s.summary());
    }
}
