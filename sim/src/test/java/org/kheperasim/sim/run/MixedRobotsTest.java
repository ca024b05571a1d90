package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.ArenaFormatException;
import org.kheperasim.sim.engine.model.Settings;

/** One arena with robots of several types: each gets its type's body and sensors, and the run is deterministic. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class MixedRobotsTest {
    private static final String ARENA = "khepera-arena 1\nname mixed\nsize 1000 1000\n"
            + "robot 250 500 0\nrobot 750 500 180 epuck\n"
            + "wall 0 4 1000 4 8\nwall 0 996 1000 996 8\nwall 4 0 4 1000 8\nwall 996 0 996 1000 8\n";

    private static String trace(Arena arena, long seed) {
        StringWriter out = new StringWriter();
        Simulation.builder().arena(arena).controller("Braitenberg").seed(seed).seconds(20).settings(Settings.defaults())
                .trace(out).sampleMillis(50).run();
        return out.toString();
    }

    @Test
    void aKheperaAndAnEpuckShareAnArenaAndTheRunRepeatsByteForByte() {
        Arena arena = ArenaFormat.parse(ARENA, "mixed.arena");
        assertEquals("khepera1", arena.robotType(0).name());
        assertEquals("epuck", arena.robotType(1).name());
        String a = trace(arena, 3);
        assertEquals(a, trace(arena, 3));
        assertTrue(a.contains("\n# robot-types 0=khepera1 1=epuck\n"), a.substring(0, 400));
        // The arena writes its robot line back with the type, and reads back to the same arena.
        String written = ArenaFormat.write(arena);
        assertTrue(written.contains("robot 750 500 180 epuck\n"), written);
        assertEquals(arena, ArenaFormat.parse(written, "again.arena"));
    }

    @Test
    void aRunOfKheperasAloneNamesNoTypes() {
        String a = trace(ArenaFormat.parse(ARENA.replace(" epuck", ""), "kheperas.arena"), 3);
        assertFalse(a.contains("robot-types"), a.substring(0, 400));
    }

    @Test
    void anUnknownTypeIsRefusedOnItsLine() {
        ArenaFormatException e = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse(ARENA.replace(" epuck", " epuk"), "m.arena"));
        assertEquals("m.arena:5: robot type 'epuk' is not a bundled robot; use one of khepera1, khepera2, epuck, wsu,"
                + " or the path of a robot file (.yaml) or of a calibration (.calibration)", e.getMessage());
        ArenaFormatException f = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse(ARENA.replace(" epuck", " robots/none.yaml"), "m.arena"));
        assertTrue(f.getMessage().startsWith("m.arena:5: robot file 'robots/none.yaml': no such robot file;"), f.getMessage());
    }
}
