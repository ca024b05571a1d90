package org.kheperasim.sim.cli;

import java.util.concurrent.Callable;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.gui.GuiBench;
import org.kheperasim.sim.gui.GuiLauncher;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code gui-bench}: the window's figures (start-up, frames per second, engine speed with the window open). */
@Command(name = "gui-bench", mixinStandardHelpOptions = true,
        description = {"Open the window and measure: start-up time, frames/s at x1 with every panel on,",
            "and the engine's speed at 'as fast as possible' with the window open against headless. Needs a display."})
final class GuiBenchCommand implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "5", converter = CliNumbers.PositiveSeconds.class,
            description = "real seconds per measurement (default: ${DEFAULT-VALUE})")
    double seconds;

    @Override
    public Integer call() throws Exception {
        try {
            GuiBench.run(System.out, seconds);
            return 0;
        } catch (GuiLauncher.NoDisplayException e) {
            System.err.println(ToolErrors.prefix("khepera-sim") + e.getMessage());
            return ExitCodes.BAD_INPUT;
        }
    }
}
