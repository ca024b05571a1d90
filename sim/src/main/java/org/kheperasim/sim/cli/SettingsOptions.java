package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.sim.engine.model.Settings;
import picocli.CommandLine.Option;

/** The options that change a robot's settings, shared by the commands that build one ({@code run}, {@code serve}). */
final class SettingsOptions {
    @Option(names = "--baud", paramLabel = "N", converter = CliNumbers.Baud.class,
            description = "serial link speed the timing follows: 9600, 19200, 38400, 57600 or 115200 (default 38400;"
                    + " --set link.baud=N takes any speed in 300..1000000)")
    Integer baud;

    @Option(names = "--noise", paramLabel = "X", converter = CliNumbers.NonNegativeDecimal.class,
            description = "scale all noise, per reading and per robot (0 = none, 1 = default)")
    Double noise;

    @Option(names = "--set", paramLabel = "KEY=VALUE",
            description = "change a setting, e.g. prox.3.gain=0.5 (see the 'settings' command)")
    List<String> set = new ArrayList<>();

    /**
     * @return the defaults with these options applied
     * @throws IllegalArgumentException naming a bad key or value
     */
    Settings settings() {
        Settings settings = Settings.defaults();
        if (noise != null) {
            settings = settings.withNoise(noise);
        }
        if (baud != null) {
            settings = settings.with("link.baud", Integer.toString(baud));
        }
        for (String s : set) {
            settings = settings.with(s);
        }
        return settings;
    }
}
