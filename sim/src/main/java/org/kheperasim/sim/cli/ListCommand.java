package org.kheperasim.sim.cli;

import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.ControllerCatalog;
import picocli.CommandLine.Command;

/** {@code list}: the bundled arenas and controllers. */
@Command(name = "list", mixinStandardHelpOptions = true, description = "List the bundled arenas and controllers.")
final class ListCommand implements Runnable {
    @Override
    public void run() {
        System.out.println("arenas:      " + String.join(" ", ArenaFormat.bundledNames()));
        System.out.println("controllers: " + String.join(" ", ControllerCatalog.bundled()));
    }
}
