package org.kheperasim.sim.cli;

import java.util.Map;
import org.kheperasim.sim.engine.model.Settings;
import picocli.CommandLine.Command;

/** {@code settings}: every setting with its default and meaning. */
@Command(name = "settings", mixinStandardHelpOptions = true,
        description = "List every setting (for --set KEY=VALUE) with its default and meaning.")
final class SettingsCommand implements Runnable {
    @Override
    public void run() {
        for (Map.Entry<String, String[]> e : Settings.catalogue().entrySet()) {
            System.out.printf("%-26s %-9s %s%n", e.getKey(), e.getValue()[0], e.getValue()[1]);
        }
    }
}
