package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Every command's {@code --help} wraps between words: a file name, a setting, an option's value
 * ({@code run.trace}, {@code link.baud=N}, {@code N:KEY=VALUE}) is never cut in two, as picocli cut
 * them after dots and colons; lines keep to 80 characters; verify's help gives one exit-status
 * table, its own.
 */
class HelpTextTest {

    private static List<CommandLine> everyCommand() {
        List<CommandLine> out = new ArrayList<>();
        CommandLine top = Main.commandLine();
        out.add(top);
        for (CommandLine sub : top.getSubcommands().values()) {
            out.add(sub);
            out.addAll(sub.getSubcommands().values());
        }
        return out;
    }

    private static Set<String> words(String text) {
        return new HashSet<>(List.of(text.strip().split("\\s+")));
    }

    @Test
    void noNameIsCutInTwoAndNoLineIsLongerThan80() {
        int checked = 0;
        for (CommandLine cl : everyCommand()) {
            if (cl.getCommand() instanceof CommandLine.HelpCommand) {
                continue;
            }
            CommandSpec spec = cl.getCommandSpec();
            String help = cl.getUsageMessage(CommandLine.Help.Ansi.OFF);
            Set<String> shown = words(help);
            List<String> texts = new ArrayList<>(List.of(spec.usageMessage().description()));
            texts.addAll(List.of(spec.usageMessage().footer()));
            for (OptionSpec o : spec.options()) {
                texts.addAll(List.of(o.description()));
            }
            for (String text : texts) {
                for (String w : words(text)) {
                    if (w.matches(".*\\w[.:=/-]\\w.*")) {
                        assertTrue(shown.contains(w), spec.qualifiedName() + " --help cuts '" + w + "':\n" + help);
                        checked++;
                    }
                }
            }
            for (String line : help.split("\\R")) {
                assertTrue(line.length() <= 80 || !line.strip().contains(" "), spec.qualifiedName() + ": " + line.length()
                        + " characters: " + line);
            }
        }
        assertTrue(checked > 40, "names with dots, colons and equals signs were checked: " + checked);
        String run = Main.commandLine().getSubcommands().get("run").getUsageMessage(CommandLine.Help.Ansi.OFF);
        assertTrue(run.contains("[--robot=N:KEY=VALUE]"), run);
    }

    @Test
    void verifysHelpGivesItsOwnExitStatusOnce() {
        String help = Main.commandLine().getSubcommands().get("verify").getUsageMessage(CommandLine.Help.Ansi.OFF);
        assertEquals(1, help.split("Exit status", -1).length - 1, help);
        assertTrue(help.contains("Exit status: 0 identical; 1 it differs; 2 bad input"), help);
        String lean = Main.commandLineFor(new String[] {"verify", "--help"}).getSubcommands().get("verify")
                .getUsageMessage(CommandLine.Help.Ansi.OFF);
        assertEquals(help, lean, "the lean command line (one subcommand built) prints the same help");
    }
}
