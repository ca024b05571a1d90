package org.kheperasim.sim.cli;

import java.util.Iterator;
import org.kheperasim.sim.arena.ArenaFormat;

/**
 * The bundled arenas' names, for {@code --help} ({@code ${COMPLETION-CANDIDATES}}), {@code list} and shell completion.
 */
final class BundledArenas implements Iterable<String> {
    @Override
    public Iterator<String> iterator() {
        return ArenaFormat.bundledNames().iterator();
    }
}
