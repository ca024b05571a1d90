package org.kheperasim.sim.arena.wsu;

import java.nio.file.Path;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.WsuWorldReader;

/**
 * The arena files' {@link WsuWorldReader}: {@link WsuWorld#read(Path, Consumer)}, registered in
 * {@code META-INF/services/org.kheperasim.sim.arena.WsuWorldReader}.
 */
public final class WsuWorldImport implements WsuWorldReader {
    /** Made by the service loader. */
    public WsuWorldImport() {
    }

    @Override
    public Arena read(Path file, Consumer<String> warnings) {
        return WsuWorld.read(file, warnings);
    }
}
