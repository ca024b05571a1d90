package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;

/** What {@code run --sandbox} and {@code serve --sandbox} hand the same command in the box. */
final class Sandboxed {
    private Sandboxed() {
    }

    /**
     * @param spec    the command as parsed
     * @param command its name
     * @return its arguments as given, after the command's name, without {@code --sandbox}
     */
    static List<String> argsAfter(CommandSpec spec, String command) {
        List<String> all = spec.commandLine().getParseResult().originalArgs();
        int at = all.indexOf(command);
        List<String> args = new ArrayList<>(all.subList(at + 1, all.size()));
        args.remove("--sandbox");
        return args;
    }
}
