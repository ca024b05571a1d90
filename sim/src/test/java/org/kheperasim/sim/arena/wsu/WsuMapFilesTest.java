package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Wall;

/**
 * Three real world files of the original WSU simulator, from a course that used it, read from
 * {@code ../shared/wsu-maps/} beside the repository (never copied into it). Skipped where the
 * folder is absent, as on a student's laptop; with {@code CI=true} its absence is a failure.
 */
class WsuMapFilesTest {
    private static Path maps;

    @BeforeAll
    static void findTheMaps() {
        maps = mapsFolder();
    }

    /**
     * @return the folder of the real WSU world files; skips the calling test where it is absent,
     *     and fails it under {@code CI=true}
     */
    static Path mapsFolder() {
        Path folder = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("../shared/wsu-maps").normalize();
        if (!Files.isDirectory(folder)) {
            if ("true".equals(System.getenv("CI"))) {
                fail("the real WSU world files are not at " + folder.toAbsolutePath() + ", and CI=true requires"
                        + " these tests to run: check out shared/ beside the repository");
            }
            Assumptions.assumeTrue(false, "no real WSU world files at " + folder.toAbsolutePath()
                    + " (the folder shared/wsu-maps/ beside the repository; CI has it)");
        }
        return folder;
    }

    private final List<String> warnings = new ArrayList<>();

    private WsuWorld.Imported read(String name) {
        WsuWorld.Imported w = WsuWorld.importWorld(maps.resolve(name), warnings::add);
        assertEquals(List.of(), warnings, name);
        assertEquals(name, w.arena().name());
        assertEquals(WsuWorldReaderTest.BORDER, w.arena().walls().subList(0, 4), "the border comes first");
        assertEquals(List.of(WsuWorldReaderTest.START), w.arena().robots(), "the original's start is free");
        assertEquals(w.arena(), ArenaFormat.parse(ArenaFormat.write(w.arena()), name), "a valid arena file");
        return w;
    }

    private static List<Wall> inside(Arena a) {
        return a.walls().subList(4, a.walls().size());
    }

    @Test
    void maze() {
        WsuWorld.Imported w = read("maze");
        assertEquals(33, w.walls());
        assertEquals(0, w.caps() + w.balls() + w.lights());
        List<Wall> walls = inside(w.arena());
        assertTrue(walls.stream().anyMatch(x -> x.x1() == x.x2()) && walls.stream().anyMatch(x -> x.y1() == x.y2()),
                "both orientations: " + walls);
        assertTrue(walls.size() < 33, "bars laid end to end are joined: " + walls.size());
    }

    @Test
    void gripperMover() {
        WsuWorld.Imported w = read("gripper-mover1");
        assertEquals(20, w.walls());
        assertEquals(1, w.caps() + w.balls());
        assertEquals(0, w.lights());
        assertEquals(1, w.arena().caps().size());
        assertTrue(inside(w.arena()).stream().allMatch(x -> x.x1() == x.x2()), "all vertical: " + w.arena().walls());
    }

    @Test
    void behaviourGates() {
        WsuWorld.Imported w = read("behavior1-gates1");
        assertEquals(12, w.walls());
        assertEquals(6, w.lights());
        assertEquals(6, w.arena().lights().size());
        assertEquals(0, w.arena().caps().size());
        assertTrue(inside(w.arena()).stream().allMatch(x -> x.y1() == x.y2()), "all horizontal: " + w.arena().walls());
    }

    @Test
    void wherePathsBecomeArenasTheRealFilesAreRecognisedByContent() {
        Path maze = maps.resolve("maze");
        assertTrue(ArenaFiles.isWsuWorld(maze));
        Arena a = ArenaFiles.load(maze);
        assertEquals(WsuWorld.read(maze, w -> { }), a);
        assertEquals(a, ArenaFormat.resolve(maze.toString()), "the command line's --arena FILE");
    }
}
