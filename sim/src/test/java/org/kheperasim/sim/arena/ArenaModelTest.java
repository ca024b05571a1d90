package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class ArenaModelTest {

    private static Arena tiny(List<Region> regions) {
        return new Arena("t", 100, 100, List.of(new Pose(50, 50, 0)), List.of(), List.of(), List.of(), regions);
    }

    @Test
    void regionNormalisesCornersAndContainsItsEdges() {
        Region r = new Region("goal", 30, 40, 10, 20);
        assertEquals(new Region("goal", 10, 20, 30, 40), r);
        assertTrue(r.contains(10, 20));
        assertTrue(r.contains(30, 40));
        assertTrue(r.contains(15, 35));
        assertFalse(r.contains(9.99, 30));
        assertFalse(r.contains(20, 40.01));
    }

    @Test
    void regionRejectsBadNamesAndEmptyRectangles() {
        assertThrows(IllegalArgumentException.class, () -> new Region("a b", 0, 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Region("", 0, 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Region("flat", 0, 5, 10, 5));
    }

    @Test
    void lightDefaultsAndDirection() {
        Light all = new Light(100, 100);
        assertEquals(6, all.radius());
        assertEquals(400, all.range());
        assertEquals(1, all.intensity());
        assertEquals(360, all.spreadDeg());
        assertFalse(all.isDirectional());
        assertTrue(all.shinesOn(100, 499));
        assertFalse(all.shinesOn(100, 501));

        Light up = new Light(100, 100, 6, 400, 1, 90, 60);
        assertTrue(up.isDirectional());
        assertTrue(up.shinesOn(100, 300));
        assertTrue(up.shinesOn(100 + 100 * StrictMath.tan(StrictMath.toRadians(29)), 200));
        assertFalse(up.shinesOn(100 + 100 * StrictMath.tan(StrictMath.toRadians(31)), 200));
        assertFalse(up.shinesOn(100, 0));
        // The cone wraps around 0/360 degrees.
        Light east = new Light(0, 0, 6, 400, 1, 350, 40);
        assertTrue(east.shinesOn(100, 10));
        assertFalse(east.shinesOn(100, 50));
    }

    @Test
    void lightRejectsBadNumbers() {
        assertThrows(IllegalArgumentException.class, () -> new Light(0, 0, 0, 400, 1, 0, 360));
        assertThrows(IllegalArgumentException.class, () -> new Light(0, 0, 6, -1, 1, 0, 360));
        assertThrows(IllegalArgumentException.class, () -> new Light(0, 0, 6, 400, -0.5, 0, 360));
        assertThrows(IllegalArgumentException.class, () -> new Light(0, 0, 6, 400, 1, 0, 361));
        assertThrows(IllegalArgumentException.class, () -> new Light(0, 0, 6, 400, 1, Double.NaN, 360));
    }

    @Test
    void recordsCheckNumbersAndTurnNegativeZeroIntoZero() {
        assertEquals(new Pose(0, 0, 0), new Pose(-0.0, -0.0, -0.0));
        assertThrows(IllegalArgumentException.class, () -> new Pose(Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new Wall(0, 0, 1, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> new Wall(5, 5, 5, 5, 8));
        assertThrows(IllegalArgumentException.class, () -> new Cap(0, 0, -1));
        assertEquals(9, new Cap(1, 2).radius());
    }

    @Test
    void arenaCopiesItsListsAndFindsRegions() {
        List<Region> regions = new ArrayList<>(List.of(new Region("a", 0, 0, 10, 10)));
        Arena arena = tiny(regions);
        regions.add(new Region("b", 0, 0, 20, 20));
        assertEquals(1, arena.regions().size());
        assertThrows(UnsupportedOperationException.class, () -> arena.walls().add(new Wall(0, 0, 1, 1, 1)));
        assertEquals(Optional.of(new Region("a", 0, 0, 10, 10)), arena.region("a"));
        assertEquals(Optional.empty(), arena.region("b"));
    }

    @Test
    void arenaChecksItsInvariants() {
        assertThrows(IllegalArgumentException.class, () -> tiny(List.of(
                new Region("a", 0, 0, 10, 10), new Region("a", 5, 5, 10, 10))));
        assertThrows(IllegalArgumentException.class, () -> new Arena("t", 100, 100, List.of(),
                List.of(), List.of(), List.of(), List.of()));
        assertThrows(IllegalArgumentException.class, () -> new Arena("t", 0, 100,
                List.of(new Pose(1, 1, 0)), List.of(), List.of(), List.of(), List.of()));
        assertThrows(IllegalArgumentException.class, () -> new Arena("has space", 100, 100,
                List.of(new Pose(1, 1, 0)), List.of(), List.of(), List.of(), List.of()));
    }

    @Test
    void packageIsHeadless() throws IOException {
        Path dir = Path.of(System.getProperty("kheperasim.repoRoot", ".."),
                "sim/src/main/java/org/kheperasim/sim/arena");
        try (Stream<Path> files = Files.list(dir)) {
            List<Path> sources = files.filter(p -> p.toString().endsWith(".java")).toList();
            assertFalse(sources.isEmpty());
            for (Path p : sources) {
                String text = Files.readString(p);
                assertFalse(text.contains("java.awt") || text.contains("javax.swing"), p + " uses AWT or Swing");
            }
        }
    }
}
