package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * A command line names a subcommand: only that subcommand is built, found by the naming of the
 * classes. Every subcommand of the full command line must be found so, and nothing else.
 */
class MainSubcommandsTest {

    @Test
    void everySubcommandIsFoundByItsName() {
        Class<?>[] all = Main.class.getAnnotation(Command.class).subcommands();
        int found = 0;
        for (Class<?> type : all) {
            if (type == CommandLine.HelpCommand.class) {
                continue;
            }
            String name = type.getAnnotation(Command.class).name();
            assertEquals(type, Main.subcommand(name), name + " is " + type.getSimpleName());
            found++;
        }
        assertEquals(all.length - 1, found, Arrays.toString(all));
    }

    @Test
    void otherWordsAreNoSubcommand() {
        for (String word : new String[] {"help", "merge", "main", "Run", "--help", "", "run-", "gui--bench", "x.y"}) {
            assertNull(Main.subcommand(word), word);
        }
    }

    @Test
    void theLeanCommandLineParsesAsTheFullOne() {
        String[] args = {"run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "2"};
        CommandLine lean = Main.commandLineFor(args);
        assertEquals(1, lean.getSubcommands().size());
        CommandLine.ParseResult parsed = lean.parseArgs(args);
        assertEquals(RunCommand.class, parsed.subcommand().commandSpec().userObject().getClass());
        assertEquals(Main.class.getAnnotation(Command.class).subcommands().length,
                Main.commandLineFor(new String[] {"--help"}).getSubcommands().size());
    }
}
