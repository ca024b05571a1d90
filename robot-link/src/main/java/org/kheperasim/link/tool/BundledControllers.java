package org.kheperasim.link.tool;

import java.util.Iterator;
import org.kheperasim.api.binding.ControllerNames;

/** The bundled controllers' names, for {@code --help} ({@code ${COMPLETION-CANDIDATES}}) and shell completion. */
public final class BundledControllers implements Iterable<String> {
    @Override
    public Iterator<String> iterator() {
        return ControllerNames.bundled(BundledControllers.class.getClassLoader()).iterator();
    }
}
