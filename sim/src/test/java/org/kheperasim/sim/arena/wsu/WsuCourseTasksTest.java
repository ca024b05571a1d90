package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.ArenaFormatException;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * The WSU course's own worlds with tasks of their own: the arena files of {@code
 * docs/examples/wsu-course/} build on the real world files ({@code wsu-world}) and score runs in them.
 */
class WsuCourseTasksTest {
    private static Path maps;
    private static final Path EXAMPLES = Path.of(System.getProperty("kheperasim.repoRoot", ".."))
            .resolve("docs/examples/wsu-course");

    @TempDir
    Path dir;

    @BeforeAll
    static void findTheMaps() {
        maps = WsuMapFilesTest.mapsFolder();
    }

    /** The example arena beside a copy of its world, as an instructor keeps them. */
    private Arena course(String world) throws IOException {
        Files.copy(maps.resolve(world), dir.resolve(world));
        Path arena = dir.resolve(world + "-course.arena");
        Files.copy(EXAMPLES.resolve(arena.getFileName()), arena);
        Arena a = ArenaFiles.load(arena);
        Arena w = WsuWorld.read(maps.resolve(world), note -> { });
        assertEquals(w.walls(), a.walls(), "the world's walls, border first");
        assertEquals(w.lights(), a.lights());
        assertEquals(w.caps(), a.caps());
        assertEquals(w.robots(), a.robots(), "the original's start pose");
        assertEquals(w.width(), a.width());
        return a;
    }

    private static Score run(Arena a, String controller, RunResult[] out) {
        RunResult r = Simulation.builder().arena(a).controller(controller).seed(1)
                .seconds(a.assignment().timeLimitSeconds()).run();
        out[0] = r;
        return Score.of(a, RunFacts.of(r));
    }

    @Test
    void gatesScoreTheGatesPassed() throws IOException {
        Arena a = course("behavior1-gates1");
        assertEquals(6, a.lights().size());
        assertEquals(List.of("gate1", "gate2", "gate3"), a.regions().stream().map(r -> r.name()).toList());
        assertEquals(600, a.assignment().timeLimitSeconds());
        RunResult[] r = new RunResult[1];
        Score s = run(a, "Braitenberg", r);
        long passed = r[0].first().regionsEntered().keySet().stream().filter(n -> n.startsWith("gate")).count();
        assertEquals(passed / 3.0, s.parts().get(0).fraction(), 1e-12, s.summary());
        assertTrue(passed > 0, "Braitenberg wanders through a gate in ten minutes: " + s.summary());
    }

    @Test
    void mazeScoresCoverage() throws IOException {
        Arena a = course("maze");
        RunResult[] r = new RunResult[1];
        Score s = run(a, "WallFollower", r);
        double visited = r[0].first().visitedPercent();
        assertEquals(StrictMath.min(1, visited / 40), s.parts().get(0).fraction(), 1e-12, s.summary());
        assertTrue(visited > 10, s.summary());
    }

    @Test
    void gripperMoverScoresTheCapAtTheFarEnd() throws IOException {
        Arena a = course("gripper-mover1");
        assertEquals(1, a.caps().size());
        Score untouched = Score.of(a, new RunFacts(600, java.util.Map.of(), 0, java.util.Map.of("far-end", 0), 1));
        Score done = Score.of(a, new RunFacts(600, java.util.Map.of(), 0, java.util.Map.of("far-end", 1), 1));
        assertEquals(0, untouched.percent());
        assertEquals(100, done.percent());
    }

    @Test
    void robotLinesReplaceTheWorldsStartAndTheFileCanAddItems() throws IOException {
        Files.copy(maps.resolve("maze"), dir.resolve("maze"));
        Path f = dir.resolve("two.arena");
        Files.writeString(f, "khepera-arena 1\nwsu-world maze\nrobot 150 150 90\nrobot 150 1100 0\ncap 600 600\n");
        Arena a = ArenaFiles.load(f);
        assertEquals(List.of(new Pose(150, 150, 90), new Pose(150, 1100, 0)), a.robots());
        assertEquals(1, a.caps().size());
        assertEquals("two", a.name());
    }

    @Test
    void mistakesNameTheLineAndTheFix() throws IOException {
        Files.copy(maps.resolve("maze"), dir.resolve("maze"));
        Files.writeString(dir.resolve("text.arena"), "khepera-arena 1\nsize 100 100\nrobot 50 50 0\n");
        assertEquals(dir.resolve("a.arena") + ":2: wsu-world: there is no file 'mase' (looked for " + dir.resolve("mase")
                + "); give the WSU world file's path, relative to this arena file's folder",
                refused("khepera-arena 1\nwsu-world mase\n"));
        assertTrue(refused("khepera-arena 1\nwsu-world text.arena\n").contains(":2: wsu-world: " + dir.resolve("text.arena")
                + " is not a WSU world file"));
        assertTrue(refused("khepera-arena 1\nwsu-world maze\nsize 100 100\n")
                .endsWith(":3: the wsu-world on line 2 sets the size; remove this 'size' line"));
        assertTrue(refused("khepera-arena 1\nsize 100 100\nwsu-world maze\n").contains(":3: wsu-world sets the size"));
        assertTrue(refused("khepera-arena 1\nwsu-world maze\nwsu-world maze\n").contains(":3: a second 'wsu-world' line"));
        ArenaFormatException e = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse("khepera-arena 1\nwsu-world maze\n", "pasted.arena"));
        assertTrue(e.getMessage().startsWith("pasted.arena:2: wsu-world works only in an arena file"), e.getMessage());
    }

    private String refused(String text) throws IOException {
        Path f = dir.resolve("a.arena");
        Files.writeString(f, text);
        return assertThrows(ArenaFormatException.class, () -> ArenaFiles.load(f)).getMessage();
    }
}
