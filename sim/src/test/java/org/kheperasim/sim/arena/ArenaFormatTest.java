package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class ArenaFormatTest {

    private static final String HEAD = "khepera-arena 1\nsize 1000 1000\nrobot 500 500 0\n";

    private static void assertRoundTrip(Arena a) {
        String text = ArenaFormat.write(a);
        Arena back = ArenaFormat.parse(text, "x");
        assertEquals(a, back);
        assertEquals(text, ArenaFormat.write(back));
    }

    @ParameterizedTest
    @ValueSource(strings = {"lab", "maze", "two-rooms"})
    void bundledArenasRoundTrip(String name) {
        assertRoundTrip(ArenaFormat.loadBundled(name));
    }

    @ParameterizedTest
    @ValueSource(strings = {"lab", "maze", "two-rooms"})
    void repositoryFilesAreTheBundledOnes(String name) {
        Path file = Path.of(System.getProperty("kheperasim.repoRoot", ".."), "arenas", name + ".arena");
        assertEquals(ArenaFormat.loadBundled(name), ArenaFormat.load(file));
    }

    @Test
    void generatedArenasWithEveryKindOfItemRoundTrip() {
        SplittableRandom rnd = new SplittableRandom(20240611);
        for (int n = 0; n < 50; n++) {
            double w = 800 + rnd.nextDouble() * 800;
            double h = 800 + rnd.nextDouble() * 800;
            // Robots along the bottom, everything solid in the top half, so every start is clear.
            List<Pose> robots = new ArrayList<>();
            for (int i = 0; i < 1 + rnd.nextInt(3); i++) {
                robots.add(new Pose(60 + i * 120 + rnd.nextDouble() * 40, 60 + rnd.nextDouble() * 40,
                        rnd.nextDouble() * 720 - 360));
            }
            List<Wall> walls = new ArrayList<>();
            for (int i = 0; i < 1 + rnd.nextInt(5); i++) {
                walls.add(new Wall(rnd.nextDouble() * w, h / 2 + rnd.nextDouble() * h / 2,
                        rnd.nextDouble() * w, h / 2 + rnd.nextDouble() * h / 2, 0.5 + rnd.nextDouble() * 20));
            }
            List<Light> lights = List.of(
                    new Light(rnd.nextDouble() * w, h / 2 + rnd.nextDouble() * h / 2),
                    new Light(rnd.nextDouble() * w, h / 2 + rnd.nextDouble() * h / 2, 1 + rnd.nextDouble() * 9,
                            100 + rnd.nextDouble() * 500, rnd.nextDouble() * 3, rnd.nextDouble() * 360,
                            1 + rnd.nextDouble() * 359));
            List<Cap> caps = List.of(new Cap(rnd.nextDouble() * w, rnd.nextDouble() * h),
                    new Cap(rnd.nextDouble() * w, rnd.nextDouble() * h, 0.001 + rnd.nextDouble() * 20));
            List<Region> regions = List.of(
                    new Region("r_" + n, rnd.nextDouble() * w, rnd.nextDouble() * h, rnd.nextDouble() * w,
                            rnd.nextDouble() * h),
                    new Region("whole-" + n, 0, 0, w, h));
            assertRoundTrip(new Arena("gen" + n, w, h, robots, walls, lights, caps, regions));
        }
    }

    @Test
    void writesCanonicalText() {
        String text = """
                # a hand-written file
                khepera-arena 1   # header
                cap 550 500 radius 12.5
                region start 200 200 0 0
                light 600 600 spread 60 direction 90
                light 300 600 range 400.000
                robot 100 100.50 90
                size 1000 8e2
                cap 500 500 radius 9
                wall 0 4 1000 4 8
                name demo
                """;
        assertEquals("""
                khepera-arena 1
                name demo
                size 1000 800
                robot 100 100.5 90
                wall 0 4 1000 4 8
                light 600 600 direction 90 spread 60
                light 300 600
                cap 550 500 radius 12.5
                cap 500 500
                region start 0 0 200 200
                """, ArenaFormat.write(ArenaFormat.parse(text, "demo.arena")));
    }

    @Test
    void documentedExampleSavesAsDocumented() throws IOException {
        String doc = Files.readString(Path.of(System.getProperty("kheperasim.repoRoot", ".."),
                "docs", "arena-format.md"));
        String[] blocks = doc.substring(doc.indexOf("## A full example")).split("```");
        Arena example = ArenaFormat.parse(blocks[1].strip() + "\n", "example.arena");
        assertEquals(2, example.robots().size());
        assertEquals(blocks[3].strip() + "\n", ArenaFormat.write(example));
    }

    @Test
    void writesNumbersShortestAndExact() {
        Arena a = new Arena("n", 1000, 1000, List.of(new Pose(1e-7 + 500, 123456.789e-3, 0.1 + 0.2)),
                List.of(), List.of(), List.of(), List.of());
        String text = ArenaFormat.write(a);
        assertTrue(text.contains("robot 500.0000001 123.456789 0.30000000000000004\n"), text);
        assertRoundTrip(a);
    }

    @Test
    void acceptsCrLfTabsAndAByteOrderMark() {
        Arena a = ArenaFormat.parse("\uFEFFkhepera-arena 1\r\nsize\t1000 1000\r\n\r\nrobot 500 500 0 # r\r\n", "w.arena");
        assertEquals(new Pose(500, 500, 0), a.robots().get(0));
    }

    @Test
    void namesAnUnnamedArenaAfterItsFile() {
        assertEquals("my_lab", ArenaFormat.parse(HEAD, "some/dir/my lab.arena").name());
    }

    static Stream<Arguments> badFiles() {
        return Stream.of(
                bad("empty file", "", 1, "expected 'khepera-arena 1'"),
                bad("missing header", "size 1000 1000\nrobot 500 500 0\n", 1,
                        "expected 'khepera-arena 1' as the first line, found 'size 1000 1000'"),
                bad("header after comments", "# hello\n\nkhepera 1\n", 3, "expected 'khepera-arena 1'"),
                bad("unsupported version", "khepera-arena 2\nsize 1000 1000\n", 1,
                        "expected 'khepera-arena 1', found version '2'"),
                bad("unknown keyword", HEAD + "wal 0 0 10 10 8\n", 4,
                        "unknown keyword 'wal'; valid keywords are name, size, wsu-world, robot, wall, light, cap, region, task, time-limit"),
                bad("wall with 4 numbers", HEAD + "wall 0 0 10 10\n", 4,
                        "wall needs x1 y1 x2 y2 thickness (5 numbers, mm), got 4 values"),
                bad("robot with 2 numbers", HEAD + "robot 1 2\n", 4, "robot needs x y heading"),
                bad("size with 3 numbers", "khepera-arena 1\nsize 1 2 3\n", 2, "size needs width height"),
                bad("region without name", HEAD + "region 0 0 10 10\n", 4, "region needs name x1 y1 x2 y2"),
                bad("cap with 3 numbers", HEAD + "cap 1 2 3\n", 4, "cap needs x y, optionally followed by 'radius"),
                bad("not a number", HEAD + "wall 0 0 abc 10 8\n", 4, "wall x2 is 'abc', not a number"),
                bad("NaN", HEAD + "robot NaN 5 0\n", 4, "robot x is 'NaN'; give a finite number"),
                bad("Infinity", HEAD + "cap 5 -Infinity\n", 4, "cap y is '-Infinity'; give a finite number"),
                bad("overflow", HEAD + "light 5 1e999\n", 4, "light y is '1e999', too large"),
                bad("hex number", HEAD + "cap 0x10 5\n", 4, "cap x is '0x10', not a number"),
                bad("negative size", "khepera-arena 1\nsize -5 100\nrobot 1 1 0\n", 2,
                        "arena width is -5; it must be greater than 0 mm"),
                bad("zero thickness", HEAD + "wall 0 0 10 0 0\n", 4, "wall thickness is 0; it must be greater than 0 mm"),
                bad("zero-length wall", HEAD + "wall 5 5 5 5 8\n", 4, "wall has both ends at (5, 5)"),
                bad("negative cap radius", HEAD + "cap 5 5 radius -2\n", 4, "cap radius is -2"),
                bad("zero light radius", HEAD + "light 100 100 radius 0\n", 4, "light radius is 0"),
                bad("light spread too wide", HEAD + "light 100 100 spread 400\n", 4, "light spread is 400"),
                bad("missing size", "# c\nkhepera-arena 1\nrobot 500 500 0\n", 2, "no 'size' line; add 'size <width> <height>'"),
                bad("second size", HEAD + "size 10 10\n", 4, "a second 'size' line (the first is on line 2)"),
                bad("second name", HEAD + "name a\nname b\n", 5, "a second 'name' line (the first is on line 4)"),
                bad("bad name", HEAD + "name two words\n", 4, "name needs one word"),
                bad("no robot", "khepera-arena 1\nsize 1000 1000\nwall 0 4 1000 4 8\n", 1, "no 'robot' line"),
                bad("wall outside", HEAD + "wall 0 4 1200 4 8\n", 4,
                        "wall end at (1200, 4) lies outside the 1000 x 1000 mm arena"),
                bad("robot outside", HEAD + "robot -5 500 0\n", 4, "robot at (-5, 500) lies outside"),
                bad("light outside", HEAD + "light 100 1000.5\n", 4, "light at (100, 1000.5) lies outside"),
                bad("cap outside", HEAD + "cap 2000 5\n", 4, "cap at (2000, 5) lies outside"),
                bad("region outside", HEAD + "region r 0 0 10 1001\n", 4, "region corner at (10, 1001) lies outside"),
                bad("duplicate region", HEAD + "region a 0 0 10 10\n\nregion a 20 20 30 30\n", 6,
                        "region name 'a' is already used on line 4"),
                bad("bad region name", HEAD + "region a.b 0 0 10 10\n", 4, "region name 'a.b' is not allowed"),
                bad("empty region", HEAD + "region a 0 5 10 5\n", 4, "region 'a' has no area"),
                bad("robot on a wall, wall later", "khepera-arena 1\nsize 1000 1000\nrobot 500 500 0\nrobot 100 100 0\n"
                        + "wall 520 0 520 1000 8\n", 3, "robot at (500, 500) overlaps a wall"),
                bad("robot on a light", HEAD + "light 530 500\n", 3, "robot at (500, 500) overlaps a light"),
                bad("robot at the edge", HEAD + "robot 20 700 0\n", 4, "robot at (20, 700) overlaps the edge of the arena"),
                bad("robots overlapping", HEAD + "robot 540 500 0\n", 4,
                        "overlaps the robot on line 3: their centres are 40.0 mm apart"),
                bad("unknown light keyword", HEAD + "light 100 100 rnge 5\n", 4,
                        "unknown light keyword 'rnge'; valid light keywords are range, intensity, radius, direction, spread"),
                bad("light keyword without value", HEAD + "light 100 100 range\n", 4, "light keyword 'range' needs a value"),
                bad("light keyword twice", HEAD + "light 100 100 range 5 range 6\n", 4, "light keyword 'range' appears twice"),
                bad("light number instead of keyword", HEAD + "light 100 100 5\n", 4, "a number '5' where a keyword belongs"),
                bad("unknown cap keyword", HEAD + "cap 100 100 size 5\n", 4, "unknown cap keyword 'size'"));
    }

    private static Arguments bad(String what, String text, int line, String fragment) {
        return Arguments.of(what, text, line, fragment);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badFiles")
    void refusesBadFilesNamingTheLine(String what, String text, int line, String fragment) {
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(text, "test.arena"));
        assertEquals("test.arena", e.source());
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith("test.arena:" + line + ": "), e.getMessage());
        assertTrue(e.getMessage().contains(fragment), e.getMessage());
    }

    @Test
    void loadNamesTheFileInErrors(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("maze.arena");
        Files.writeString(file, "khepera-arena 7\n");
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.load(file));
        assertTrue(e.getMessage().startsWith(file + ":1: expected 'khepera-arena 1'"), e.getMessage());
        assertThrows(UncheckedIOException.class, () -> ArenaFormat.load(dir.resolve("missing.arena")));
    }

    @Test
    void resolvesPathsFirstThenBundledNames(@TempDir Path dir) {
        assertEquals(ArenaFormat.loadBundled("maze"), ArenaFormat.resolve("maze"));
        Arena mine = ArenaFormat.parse(HEAD + "name mine\n", "mine.arena");
        Path file = dir.resolve("mine.arena");
        ArenaFormat.save(mine, file);
        assertEquals(mine, ArenaFormat.resolve(file.toString()));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ArenaFormat.resolve("nowhere"));
        assertTrue(e.getMessage().contains("'nowhere'") && e.getMessage().contains("lab, maze-easy, maze")
                && e.getMessage().contains("path"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ArenaFormat.loadBundled("nowhere"));
        assertThrows(IllegalArgumentException.class, () -> ArenaFormat.loadBundled("../pom"));
        assertEquals(List.of("lab", "maze-easy", "maze", "maze-hard", "beacon-maze", "two-rooms"), ArenaFormat.bundledNames());
    }

    @Test
    void savesAtomicallyLeavingNoTemporaryFiles(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("saved.arena");
        Arena lab = ArenaFormat.loadBundled("lab");
        ArenaFormat.save(lab, file);
        Arena maze = ArenaFormat.loadBundled("maze");
        ArenaFormat.save(maze, file);
        assertEquals(ArenaFormat.write(maze), Files.readString(file));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
        Path nowhere = dir.resolve("no-such-dir").resolve("x.arena");
        assertThrows(UncheckedIOException.class, () -> ArenaFormat.save(lab, nowhere));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
    }

    @Test
    void hashIgnoresCommentsAndLayoutButNotContent() {
        Arena a = ArenaFormat.parse(HEAD + "# note\nwall 0 4 1000 4 8\n", "a.arena");
        Arena b = ArenaFormat.parse("khepera-arena 1\nwall 0 4 1000 4.0 8   # same\nrobot 500 500 0\nsize 1000 1000\n",
                "a.arena");
        Arena c = ArenaFormat.parse(HEAD + "wall 0 4 1000 5 8\n", "a.arena");
        assertEquals(64, ArenaFormat.sha256(a).length());
        assertTrue(ArenaFormat.sha256(a).matches("[0-9a-f]{64}"));
        assertEquals(ArenaFormat.sha256(a), ArenaFormat.sha256(b));
        assertNotEquals(ArenaFormat.sha256(a), ArenaFormat.sha256(c));
    }
}
