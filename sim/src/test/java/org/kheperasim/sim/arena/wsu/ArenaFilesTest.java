package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.light;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.ArenaFormatException;

/** Wherever a file becomes an arena, a WSU world file is recognised by its content. */
class ArenaFilesTest {
    @TempDir
    Path dir;

    @Test
    void aWsuWorldAndAnArenaTextFileBothLoad() throws Exception {
        Path world = dir.resolve("gates.map");
        Files.write(world, WsuWorldWriter.world(List.of(vertical(5, 100, 100), light(6, 300, 300))));
        Path text = dir.resolve("lab.arena");
        Files.writeString(text, ArenaFormat.write(ArenaFormat.loadBundled("lab")));

        assertTrue(ArenaFiles.isWsuWorld(world));
        assertFalse(ArenaFiles.isWsuWorld(text));
        assertFalse(ArenaFiles.isWsuWorld(dir.resolve("missing")));
        Arena wsu = ArenaFiles.load(world, w -> { });
        assertEquals("gates", wsu.name(), "named after the file, without its extension");
        assertEquals(1, wsu.lights().size());
        assertEquals(ArenaFormat.loadBundled("lab"), ArenaFiles.load(text));
        assertEquals(wsu, ArenaFormat.resolve(world.toString()), "the command line's --arena takes it too");
    }

    @Test
    void aDamagedWorldIsRefusedByteExactlyAndATextErrorStaysAsItWas() throws Exception {
        byte[] good = WsuWorldWriter.world(List.of(vertical(5, 100, 100)));
        Path world = dir.resolve("broken");
        Files.write(world, Arrays.copyOf(good, good.length - 10));
        WsuWorldException e = assertThrows(WsuWorldException.class, () -> ArenaFiles.load(world, w -> { }));
        assertTrue(e.getMessage().matches(java.util.regex.Pattern.quote(world.toString()) + ": byte \\d+: .*"),
                e.getMessage());

        Path text = dir.resolve("bad.arena");
        Files.writeString(text, "khepera-arena 1\nsize 1000 1000\nwal 1 2 3 4 5\n");
        ArenaFormatException t = assertThrows(ArenaFormatException.class, () -> ArenaFiles.load(text));
        assertTrue(t.getMessage().startsWith(text + ":3: "), t.getMessage());
    }

    @Test
    void warningsGoWhereTheCallerSays() throws Exception {
        Path world = dir.resolve("covered");
        Files.write(world, WsuWorldWriter.world(List.of(light(5, 255, 255))));
        List<String> warnings = new ArrayList<>();
        ArenaFiles.load(world, warnings::add);
        assertEquals(1, warnings.size(), warnings.toString());
    }
}
