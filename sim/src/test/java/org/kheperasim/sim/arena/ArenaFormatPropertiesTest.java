package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fuzz.Fuzz;
import org.kheperasim.link.fuzz.Mutations;

/**
 * Whatever the text, the arena reader either returns an arena that writes and reads back the same,
 * or throws its own error naming a line of the text; never anything else. {@code -Pfuzz} runs a
 * million inputs.
 */
@Tag("properties")
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ArenaFormatPropertiesTest {

    static final List<String> WORDS = List.of("khepera-arena", "name", "size", "robot", "wall", "light", "cap", "region",
            "range", "intensity", "radius", "direction", "spread", "#", "1", "khepera-arena 1", "end", "@");

    private static final List<String> CORPUS = List.of(
            ArenaFormat.write(ArenaFormat.loadBundled("lab")),
            ArenaFormat.write(ArenaFormat.loadBundled("two-rooms")),
            "# a comment\nkhepera-arena 1\nname small\nsize 600 400\nrobot 100 100 90 # start\nrobot 300 100 -90\n"
                    + "wall 0 4 600 4 8\nwall 300 200 300 400 8\nlight 500 300 range 300 intensity 0.5 direction 135 spread 60\n"
                    + "cap 200 300\ncap 400 300 radius 12\nregion goal 450 250 600 400\nregion start 0 0 200 200\n");

    /** A valid-looking arena of random items: most pass the line checks, many fail the whole-file ones. */
    static String randomArena(SplittableRandom r) {
        double w = 60 + r.nextDouble() * 1400;
        double h = 60 + r.nextDouble() * 1400;
        StringBuilder b = new StringBuilder("khepera-arena 1\n");
        if (r.nextBoolean()) {
            b.append("name a").append(r.nextInt(100)).append('\n');
        }
        b.append("size ").append(Mutations.number(r, 50, 1500)).append(' ').append(Mutations.number(r, 50, 1500)).append('\n');
        for (int i = 0, n = 1 + r.nextInt(3); i < n; i++) {
            b.append("robot ").append(Mutations.number(r, 0, w)).append(' ').append(Mutations.number(r, 0, h)).append(' ')
                    .append(Mutations.number(r, -360, 360)).append('\n');
        }
        for (int i = 0, n = r.nextInt(6); i < n; i++) {
            b.append("wall ").append(Mutations.number(r, 0, w)).append(' ').append(Mutations.number(r, 0, h)).append(' ')
                    .append(Mutations.number(r, 0, w)).append(' ').append(Mutations.number(r, 0, h)).append(' ')
                    .append(Mutations.number(r, 0.1, 40)).append('\n');
        }
        for (int i = 0, n = r.nextInt(3); i < n; i++) {
            b.append("light ").append(Mutations.number(r, 0, w)).append(' ').append(Mutations.number(r, 0, h));
            for (String k : List.of("range", "intensity", "radius", "direction", "spread")) {
                if (r.nextInt(3) == 0) {
                    b.append(' ').append(k).append(' ').append(Mutations.number(r, 0, 400));
                }
            }
            b.append('\n');
        }
        for (int i = 0, n = r.nextInt(4); i < n; i++) {
            b.append("cap ").append(Mutations.number(r, 0, w)).append(' ').append(Mutations.number(r, 0, h));
            b.append(r.nextBoolean() ? " radius " + Mutations.number(r, 0, 30) : "").append('\n');
        }
        for (int i = 0, n = r.nextInt(3); i < n; i++) {
            b.append("region r").append(r.nextInt(4)).append(' ').append(Mutations.number(r, 0, w)).append(' ')
                    .append(Mutations.number(r, 0, h)).append(' ').append(Mutations.number(r, 0, w)).append(' ')
                    .append(Mutations.number(r, 0, h)).append('\n');
        }
        return b.toString();
    }

    static String input(SplittableRandom r) {
        int kind = r.nextInt(10);
        if (kind < 4) {
            return Mutations.damage(r, Mutations.pick(r, CORPUS), WORDS, 4);
        }
        if (kind < 8) {
            String a = randomArena(r);
            return r.nextBoolean() ? a : Mutations.damage(r, a, WORDS, 3);
        }
        if (kind < 9) {
            return randomArena(r);
        }
        StringBuilder b = new StringBuilder(r.nextBoolean() ? "khepera-arena 1\n" : "");
        for (int i = 0, n = r.nextInt(200); i < n; i++) {
            b.append((char) (r.nextInt(10) == 0 ? r.nextInt(0x3000) : 32 + r.nextInt(95)));
        }
        return b.toString();
    }

    /** The property every reader of this project keeps. */
    static void readsOrNamesTheLine(String text) {
        Arena a;
        try {
            a = ArenaFormat.parse(text, "fuzz.arena");
        } catch (ArenaFormatException e) {
            assertEquals("fuzz.arena", e.source());
            int lines = text.split("\r\n|\r|\n", -1).length;
            assertTrue(e.line() >= 1 && e.line() <= lines, "line " + e.line() + " of " + lines + ": " + e.getMessage());
            assertTrue(e.getMessage().startsWith("fuzz.arena:" + e.line() + ": "), e.getMessage());
            assertFalse(e.getMessage().contains("this is a bug"), e.getMessage());
            assertTrue(e.getMessage().length() < 1000, "a message a person can read: " + e.getMessage().length() + " chars");
            return;
        }
        String written = ArenaFormat.write(a);
        Arena back = ArenaFormat.parse(written, "again.arena");
        assertEquals(a, back);
        assertEquals(written, ArenaFormat.write(back));
    }

    @Test
    void everyTextIsAnArenaThatRoundTripsOrAnErrorNamingItsLine() {
        Fuzz.checkText("arena format", 1500, ArenaFormatPropertiesTest::input, ArenaFormatPropertiesTest::readsOrNamesTheLine);
    }
}
