package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Issue 14: no arena file, however made, exhausts memory or time; every refusal names its line. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ArenaLimitsTest {

    private static final String HEAD = "khepera-arena 1\nsize 1000 1000\nrobot 500 500 0\n";

    static Stream<Arguments> beyondTheLimits() {
        return Stream.of(
                bad("the 60-byte file that ran out of memory", "khepera-arena 1\nsize 100000 100000\nrobot 50 50 0\n", 2,
                        "arena size 100000 x 100000 mm is too large: each side may be at most 30000 mm"),
                bad("the height that overflowed the grid", "khepera-arena 1\nsize 1219.2 2147483648\nrobot 50 50 0\n", 2,
                        "arena size 1219.2 x 2147483648 mm is too large"),
                bad("floor larger than 500 m²", "khepera-arena 1\nsize 30000 17000\nrobot 50 50 0\n", 2,
                        "the floor may be at most 500 m²"),
                bad("wall too thick", HEAD + "wall 0 900 900 900 1001\n", 4, "wall thickness is 1001; it may be at most 1000 mm"),
                bad("heading beyond a turn", HEAD.replace("robot 500 500 0", "robot 500 500 361"), 3,
                        "robot heading is 361 degrees; give an angle from -360 to 360"),
                bad("light direction beyond a turn", HEAD + "light 100 900 direction -720\n", 4, "light direction is -720"),
                bad("light range too long", HEAD + "light 100 900 range 20001\n", 4, "light range is 20001; it may be at most 20000 mm"),
                bad("light too bright", HEAD + "light 100 900 intensity 1e6\n", 4, "light intensity is 1000000"),
                bad("lamp body too large", HEAD + "light 100 900 radius 501\n", 4, "light radius is 501"),
                bad("cap too large", HEAD + "cap 900 900 radius 51\n", 4, "cap radius is 51; it may be at most 50 mm"),
                bad("number too long", HEAD + "cap 900 " + "9".repeat(1001) + "\n", 4, "longer than 1000 characters"),
                bad("name too long", HEAD + "name " + "n".repeat(101) + "\n", 4, "at most 100 letters"),
                bad("too many robots", "khepera-arena 1\nsize 7800 7800\n"
                        + repeat(16_385, i -> "robot " + (40 + 60 * (i % 128)) + " " + (40 + 60 * (i / 128)) + " 0\n"),
                        2 + 16_385, "too many robots: an arena may have at most 16384"),
                bad("too many caps", HEAD + repeat(1001, i -> "cap 900 900\n"), 4 + 1000, "too many caps: an arena may have at most 1000"),
                bad("too many lights", HEAD + repeat(257, i -> "light 900 900\n"), 4 + 256, "too many lights"),
                bad("too many regions", HEAD + repeat(1001, i -> "region r" + i + " 0 0 10 10\n"), 4 + 1000, "too many regions"),
                bad("walls covering the floor many times over", HEAD + repeat(30, i -> "wall 0 1000 1000 0 200\n"), 4 + 12,
                        "the walls up to this one cover 4.2 times the floor's area"));
    }

    private static Arguments bad(String what, String text, int line, String fragment) {
        return Arguments.of(what, text, line, fragment);
    }

    private static String repeat(int n, java.util.function.IntFunction<String> line) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            b.append(line.apply(i));
        }
        return b.toString();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("beyondTheLimits")
    void refusesWhatIsBeyondTheLimitsNamingTheLine(String what, String text, int line, String fragment) {
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(text, "big.arena"));
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith("big.arena:" + line + ": "), e.getMessage());
        assertTrue(e.getMessage().contains(fragment), e.getMessage());
    }

    @Test
    void acceptsWhatLiesAtTheLimits() {
        Arena a = ArenaFormat.parse("khepera-arena 1\nsize 10000 2500\nrobot 50 50 -360\nwall 0 2000 10000 2000 1000\n"
                + "light 9000 100 range 20000 intensity 1000 radius 500 direction 360\ncap 5000 100 radius 50\n", "edge.arena");
        assertEquals(10000, a.width());
        assertEquals(ArenaFormat.write(a), ArenaFormat.write(ArenaFormat.parse(ArenaFormat.write(a), "again")));
    }

    /** Found by the fuzz test: the canonical form of a tiny number is long, and must still read back. */
    @Test
    void theSmallestNumbersRoundTripInCanonicalForm() {
        Arena a = ArenaFormat.parse(HEAD + "cap 4.9e-324 1e-300\nregion r 0 1e-40 10 10\n", "tiny.arena");
        String written = ArenaFormat.write(a);
        assertTrue(written.contains("cap 0.0000"), written);
        assertEquals(a, ArenaFormat.parse(written, "again.arena"));
    }

    /** Found by the fuzz run: extreme numbers made a 1059-character message; messages show them briefly. */
    @Test
    void messagesShowExtremeNumbersBriefly() {
        ArenaFormatException e = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse("khepera-arena 1\nsize 4e-324 1\nrobot 4 1e308 1\n", "x.arena"));
        assertTrue(e.getMessage().startsWith("x.arena:3: robot at (4, 1.0E308) lies outside the 4.9E-324 x 1 mm arena"),
                e.getMessage());
        assertTrue(e.getMessage().length() < 200, e.getMessage());
    }

    @Test
    void fortyThousandWholeGridWallsAreRefusedAtTheFirstWallTooMany() {
        // The input took 54 s to refuse; the count is now checked line by line, before any drawing.
        String text = HEAD + repeat(40_001, i -> "wall 0 0 1000 1000 1\n");
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(text, "walls.arena"));
        assertEquals(4 + ArenaLimits.MAX_WALLS, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("too many walls: an arena may have at most 10000"), e.getMessage());
    }

    @Test
    void tenThousandLongSlantedWallsInTheLargestArenaAreDrawnRowByRow() {
        // Each wall crosses the whole 5 x 5 m floor: a bounding-box scan would visit 4 million cells per wall.
        String text = "khepera-arena 1\nsize 5000 5000\nrobot 100 4900 0\n"
                + repeat(ArenaLimits.MAX_WALLS, i -> "wall 0 " + (i % 2000) * 0.25 + " 4500 4500 1\n");
        Arena a = ArenaFormat.parse(text, "slanted.arena");
        assertEquals(ArenaLimits.MAX_WALLS, a.walls().size());
    }

    @Test
    void aLongRunOfDigitsIsRefusedWithoutBacktracking() {
        String digits = "1".repeat(200_000) + "x";
        ArenaFormatException e = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse(HEAD + "cap 10 " + digits + "\n", "digits.arena"));
        assertEquals(4, e.line());
        assertTrue(TokenNumbers.NUMBER.matcher("9".repeat(100_000)).matches());
        assertTrue(!TokenNumbers.NUMBER.matcher("9".repeat(100_000) + ".5e").matches());
    }

    @Test
    void aFileThatIsNotUtf8IsRefusedAtTheLineOfTheBadByte(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("latin1.arena");
        byte[] head = HEAD.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        byte[] bytes = java.util.Arrays.copyOf(head, head.length + 12);
        byte[] tail = "# caf\u00e9\n".getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        System.arraycopy(tail, 0, bytes, head.length, tail.length);
        Files.write(file, java.util.Arrays.copyOf(bytes, head.length + tail.length));
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.load(file));
        assertEquals(4, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("byte 0xE9 at column 6 is not UTF-8 text"), e.getMessage());
    }

    @Test
    void aFileLargerThanAnyArenaIsRefusedWithoutReadingItAll(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("huge.arena");
        try (var ch = java.nio.channels.FileChannel.open(file, java.nio.file.StandardOpenOption.CREATE_NEW,
                java.nio.file.StandardOpenOption.WRITE, java.nio.file.StandardOpenOption.SPARSE)) {
            ch.write(java.nio.ByteBuffer.wrap(new byte[] {'#'}), ArenaLimits.MAX_FILE_BYTES + 10);
        }
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.load(file));
        assertEquals(0, e.line());
        assertTrue(e.getMessage().startsWith(file + ": the file is larger than 16 MiB, the limit for arena files"),
                e.getMessage());
    }

    @Test
    void theArenaRecordRefusesAnArenaTooLargeToDraw() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Arena("big", 1e5, 1e5,
                List.of(new Pose(50, 50, 0)), List.of(), List.of(), List.of(), List.of()));
        assertTrue(e.getMessage().contains("too large"), e.getMessage());
    }

    /** The row-by-row drawing paints exactly the cells the bounding-box scan painted. */
    @Test
    void wallsAreDrawnCellForCellAsBefore() {
        SplittableRandom rnd = new SplittableRandom(14);
        for (int n = 0; n < 400; n++) {
            double w = 100 + rnd.nextDouble() * 1200;
            double h = 100 + rnd.nextDouble() * 1200;
            double x1 = rnd.nextDouble() * w;
            double y1 = rnd.nextDouble() * h;
            double x2 = rnd.nextInt(4) == 0 ? x1 : rnd.nextDouble() * w;
            double y2 = rnd.nextInt(4) == 0 && x2 != x1 ? y1 : rnd.nextDouble() * h;
            if (x1 == x2 && y1 == y2) {
                continue;
            }
            double t = rnd.nextInt(5) == 0 ? rnd.nextDouble() * 0.5 + 0.001 : rnd.nextDouble() * 150;
            Wall wall = new Wall(x1, y1, x2, y2, t);
            Arena a = new Arena("w", w, h, List.of(new Pose(0, 0, 0)), List.of(wall), List.of(), List.of(), List.of());
            OccupancyGrid fast = OccupancyGrid.of(a);
            assertArrayEquals(bruteForce(fast.cols(), fast.rows(), wall), cells(fast), "wall " + wall + " in " + w + " x " + h);
        }
    }

    private static int[] cells(OccupancyGrid g) {
        int[] c = new int[g.cols() * g.rows()];
        for (int r = 0; r < g.rows(); r++) {
            for (int col = 0; col < g.cols(); col++) {
                c[r * g.cols() + col] = g.id(col, r);
            }
        }
        return c;
    }

    /** The drawing as it was: every cell of the bounding box tested, then the centre line. */
    private static int[] bruteForce(int cols, int rows, Wall w) {
        OccupancyGrid g = new OccupancyGrid(cols, rows);
        double half = w.thickness() / 2;
        int c0 = Math.max(0, g.col(Math.min(w.x1(), w.x2()) - half));
        int c1 = Math.min(cols - 1, g.col(Math.max(w.x1(), w.x2()) + half));
        int r0 = Math.max(0, g.row(Math.min(w.y1(), w.y2()) - half));
        int r1 = Math.min(rows - 1, g.row(Math.max(w.y1(), w.y2()) + half));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                if (WallPainter.distanceToSegment(g.cellCentreX(c), g.cellCentreY(r), w) <= half) {
                    g.set(c, r, OccupancyGrid.WALL);
                }
            }
        }
        OccupancyGrid line = OccupancyGrid.of(new Arena("l", cols * OccupancyGrid.CELL_MM, rows * OccupancyGrid.CELL_MM,
                List.of(new Pose(0, 0, 0)), List.of(new Wall(w.x1(), w.y1(), w.x2(), w.y2(), 1e-9)), List.of(), List.of(),
                List.of()));
        int[] out = cells(g);
        int[] centre = cells(line);
        for (int i = 0; i < out.length; i++) {
            out[i] = Math.max(out[i], centre[i]);
        }
        return out;
    }
}
