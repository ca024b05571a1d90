package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.ball;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.cap;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.light;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.awt.Color;
import java.io.ByteArrayOutputStream;
import java.io.ObjectOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Vector;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex;

/** WSU worlds written by the tests' own writer read back into the arena they describe. */
class WsuWorldReaderTest {
    /** The border the original always has: left, right, top, bottom (mm). */
    static final List<Wall> BORDER = List.of(
            new Wall(23.1648, 1219.2, 23.1648, 0, 46.3296),
            new Wall(1199.6928, 1219.2, 1199.6928, 0, 39.0144),
            new Wall(0, 1196.0352, 1219.2, 1196.0352, 46.3296),
            new Wall(0, 21.9456, 1219.2, 21.9456, 43.8912));
    static final Pose START = new Pose(641.2992, 577.9008, 0);

    static final List<Vertex> EVERY_KIND = List.of(vertical(5, 100, 100), horizontal(6, 200, 300), cap(7, 300, 100),
            ball(8, 320, 100), light(9, 150, 400));

    private final List<String> warnings = new ArrayList<>();

    private Arena read(byte[] bytes) {
        return WsuWorld.read(bytes, "test-world", "test-world", warnings::add);
    }

    private static List<Wall> walls(Wall... inside) {
        List<Wall> all = new ArrayList<>(BORDER);
        all.addAll(List.of(inside));
        return all;
    }

    @Test
    void everyObjectKindAndBothWallOrientations() {
        Arena a = read(WsuWorldWriter.world(EVERY_KIND));
        assertEquals("test-world", a.name());
        assertEquals(1219.2, a.width());
        assertEquals(1219.2, a.height());
        assertEquals(List.of(START), a.robots(), "the original's start, centre (263, 263) px facing east");
        // Vertical: x 100..107, y 100..149 px. Horizontal: x 200..249, y 292..299 px. Ends drawn in by 4 px.
        assertEquals(walls(new Wall(253.5936, 965.6064, 253.5936, 863.1936, 19.5072),
                new Wall(497.4336, 497.4336, 599.8464, 497.4336, 19.5072)), a.walls());
        assertEquals(List.of(new Cap(742.4928, 964.3872, 10.9728), new Cap(791.2608, 964.3872, 10.9728)), a.caps(),
                "a cap and a ball, 9 px discs");
        assertEquals(List.of(new Light(385.2672, 224.3328, 19.5072, 609.6, 1, 0, 360)), a.lights(),
                "a 16 px lamp shining 250 px all around");
        assertEquals(List.of(), a.regions());
        assertEquals(List.of(), warnings);
    }

    @Test
    void anEmptyWorldIsTheBorderedLab() {
        Arena a = read(WsuWorldWriter.world(List.of()));
        assertEquals(BORDER, a.walls());
        assertEquals(List.of(START), a.robots());
        assertEquals(ArenaFormat.parse(ArenaFormat.write(a), "again"), a, "a valid arena file");
    }

    @Test
    void backReferencesResetsAndSpareCapacityChangeNothing() {
        Arena plain = read(new WsuWorldWriter().ownColours().spareCapacity(0).write(EVERY_KIND));
        Arena shared = read(new WsuWorldWriter().resetFirst().spareCapacity(7).write(EVERY_KIND));
        assertEquals(plain, shared);
        assertEquals(read(WsuWorldWriter.world(EVERY_KIND)), shared);
    }

    @Test
    void theJdksOwnSerializationOfTheSameWorldReadsTheSame() throws Exception {
        Vector<Object> world = new Vector<>(EVERY_KIND.size() + 3);
        Color red = new Color(255, 0, 0);
        for (Vertex v : EVERY_KIND) {
            world.add(new edu.wsu.KheperaSimulator.Vertex(v.id(), v.type(), v.x(), v.y(), v.theta(), red));
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(world);
        }
        assertEquals(read(WsuWorldWriter.world(EVERY_KIND)), read(bytes.toByteArray()));
    }

    @Test
    void wallsLaidEndToEndInALineBecomeOneRun() {
        Arena a = read(WsuWorldWriter.world(List.of(horizontal(5, 150, 300), horizontal(6, 100, 300),
                horizontal(7, 200, 300), vertical(8, 100, 100), vertical(9, 100, 150), horizontal(10, 100, 200))));
        // x 100..249 px at y 292..299 (three bars), x 100..107 at y 100..199 (two), and a bar that stands alone.
        assertEquals(walls(new Wall(253.5936, 497.4336, 599.8464, 497.4336, 19.5072),
                new Wall(253.5936, 965.6064, 253.5936, 741.2736, 19.5072),
                new Wall(253.5936, 741.2736, 356.0064, 741.2736, 19.5072)), a.walls());
    }

    @Test
    void objectsOutsideThePanelAreClippedOrLeftOut() {
        Arena a = read(WsuWorldWriter.world(List.of(
                vertical(5, -4, 200),        // half outside on the left: x 0..3 px remain
                horizontal(6, 480, 100),     // reaches past the right edge: x 480..499 px remain
                vertical(7, 600, 100),       // wholly outside
                cap(8, -20, -20),            // wholly outside
                cap(9, 497, 250),            // its centre past the right edge
                light(10, 100, 520))));      // wholly below
        assertEquals(walls(new Wall(4.8768, 726.6432, 4.8768, 614.4768, 9.7536),
                new Wall(1180.1856, 985.1136, 1219.2, 985.1136, 19.5072)), a.walls(),
                "the clipped bars keep their cut ends on the panel's edge");
        assertEquals(List.of(new Cap(1219.2, 598.6272, 10.9728)), a.caps());
        assertEquals(List.of(), a.lights());
        String all = String.join("\n", warnings);
        assertTrue(all.contains("wall 5 at (-4, 200) px") && all.contains("clipped"), all);
        assertTrue(all.contains("wall 7 at (600, 100) px") && all.contains("wholly outside"), all);
        assertTrue(all.contains("cap 8 at (-20, -20) px") && all.contains("cap 9 at (497, 250) px"), all);
        assertTrue(all.contains("light 10 at (100, 520) px"), all);
        assertTrue(all.contains("wall 6 at (480, 100) px (byte "), all);
        assertEquals(6, warnings.size(), all);
    }

    @Test
    void aRobotStartCoveredByAnObjectMovesToTheNearestFreeSpotWithAWarning() {
        Arena a = read(WsuWorldWriter.world(List.of(light(5, 255, 255))));
        Pose p = a.robots().get(0);
        double moved = Math.hypot(p.x() - START.x(), p.y() - START.y());
        assertTrue(moved > 0 && moved < 50, "moved " + moved + " mm to " + p);
        assertEquals(0, p.headingDeg());
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).contains("(263, 263) px") && warnings.get(0).contains("nearest free spot"),
                warnings.get(0));
        // The new start passes the arena file's own check (a robot clear of walls and lamps).
        assertEquals(a, ArenaFormat.parse(ArenaFormat.write(a), "moved"));
    }

    @Test
    void aWallOverTheStartPushesTheRobotAside() {
        Arena a = read(WsuWorldWriter.world(List.of(vertical(5, 259, 240))));
        Pose p = a.robots().get(0);
        assertTrue(Math.abs(p.x() - START.x()) > 20, "moved sideways off the wall: " + p);
        assertEquals(1, warnings.size());
    }

    @Test
    void extremeCoordinatesAreLeftOutNotOverflowed() {
        Arena a = read(WsuWorldWriter.world(List.of(vertical(5, Integer.MAX_VALUE - 3, 100),
                horizontal(6, 100, Integer.MIN_VALUE + 2), cap(7, Integer.MAX_VALUE, Integer.MIN_VALUE))));
        assertEquals(BORDER, a.walls());
        assertEquals(List.of(), a.caps());
        assertEquals(3, warnings.size(), warnings.toString());
    }

    @Test
    void anObjectOfAnUnknownKindIsLeftOutWithAWarning() {
        Arena a = read(WsuWorldWriter.world(List.of(new Vertex(5, 7, 100, 100, 0), cap(6, 300, 300))));
        assertEquals(1, a.caps().size());
        assertEquals(BORDER, a.walls());
        assertTrue(warnings.get(0).contains("kind 7") && warnings.get(0).contains("left out"), warnings.toString());
    }

    @Test
    void theMagicNumberRecognisesAWorldFile() {
        assertTrue(WsuWorld.isWsuWorld(WsuWorldWriter.world(List.of())));
        assertTrue(!WsuWorld.isWsuWorld("khepera-arena 1\n".getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        assertTrue(!WsuWorld.isWsuWorld(new byte[] {(byte) 0xAC}));
    }
}
