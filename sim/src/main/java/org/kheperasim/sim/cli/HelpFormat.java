package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import picocli.CommandLine;
import picocli.CommandLine.Help;
import picocli.CommandLine.Help.Ansi.Text;
import picocli.CommandLine.Help.Column;
import picocli.CommandLine.Help.TextTable;
import picocli.CommandLine.Model.UsageMessageSpec;

/**
 * The help's text wrapped at spaces only. Picocli breaks lines wherever Java's line breaker may,
 * which is after every dot and hyphen: {@code run.}/{@code trace}, {@code --set link.}/{@code baud=N},
 * {@code --robot=N:}/{@code KEY=VALUE}; a user who copies a name from the help gets half of it. Here
 * the synopsis, the description, the options, the parameters and the footer wrap between words, and
 * a word longer than the line stays whole on a line of its own. A command that declares its own
 * footer (verify's exit status differs from the others') keeps it, and only it.
 */
final class HelpFormat {
    /** Characters: more than any command's synopsis takes on one line. */
    private static final int SYNOPSIS_ON_ONE_LINE = 4096;
    /** How far picocli indents a description's wrapped lines. */
    private static final int WRAPPED_INDENT = 2;

    private HelpFormat() {
    }

    /**
     * @param cl a command line whose error handling (and footer) is installed
     * @return {@code cl}, with its help and every subcommand's wrapped at spaces
     */
    static CommandLine install(CommandLine cl) {
        Class<?> type = cl.getCommand().getClass();
        CommandLine.Command own = type.getAnnotation(CommandLine.Command.class);
        if (own != null && own.footer().length > 0) {
            cl.getCommandSpec().usageMessage().footer(own.footer());
        }
        Map<String, CommandLine.IHelpSectionRenderer> sections = cl.getHelpSectionMap();
        sections.put(UsageMessageSpec.SECTION_KEY_SYNOPSIS, HelpFormat::synopsis);
        sections.put(UsageMessageSpec.SECTION_KEY_DESCRIPTION,
                h -> paragraphs(h, h.commandSpec().usageMessage().description()));
        sections.put(UsageMessageSpec.SECTION_KEY_FOOTER, h -> paragraphs(h, h.commandSpec().usageMessage().footer()));
        sections.put(UsageMessageSpec.SECTION_KEY_OPTION_LIST,
                h -> h.optionList(layout(h), comparator(h), h.parameterLabelRenderer()));
        sections.put(UsageMessageSpec.SECTION_KEY_PARAMETER_LIST,
                h -> h.parameterList(layout(h), h.parameterLabelRenderer()));
        sections.put(UsageMessageSpec.SECTION_KEY_COMMAND_LIST, HelpFormat::commands);
        cl.setHelpSectionMap(sections);
        for (CommandLine sub : cl.getSubcommands().values()) {
            if (!(sub.getCommand() instanceof CommandLine.HelpCommand)) {
                install(sub);
            }
        }
        return cl;
    }

    private static java.util.Comparator<CommandLine.Model.OptionSpec> comparator(Help h) {
        return h.commandSpec().usageMessage().sortOptions()
                ? java.util.Comparator.comparing(o -> o.shortestName()) : null;
    }

    /** The options' table as picocli lays it out, with a table that wraps descriptions at spaces. */
    private static Help.Layout layout(Help h) {
        Column[] columns = h.createDefaultLayout().textTable().columns();
        Column[] copy = new Column[columns.length];
        for (int i = 0; i < columns.length; i++) {
            copy[i] = new Column(columns[i].width, columns[i].indent, columns[i].overflow);
        }
        return new Help.Layout(h.colorScheme(), new SpaceWrappingTable(h.colorScheme(), copy));
    }

    /** Lines of text (a description, a footer), each wrapped at spaces to the help's width. */
    private static String paragraphs(Help h, String[] lines) {
        StringBuilder out = new StringBuilder();
        int width = h.commandSpec().usageMessage().width();
        for (String line : lines) {
            String text = line.replace("%n", "\n");
            for (String part : text.split("\n", -1)) {
                for (String w : wrap(part, width, width, "")) {
                    out.append(w).append(System.lineSeparator());
                }
            }
        }
        return out.toString();
    }

    /** The subcommands, each with its header or the first line of its description, wrapped beside its name. */
    private static String commands(Help h) {
        Map<String, Help> subs = h.subcommands();
        if (subs.isEmpty()) {
            return "";
        }
        int nameWidth = subs.keySet().stream().mapToInt(String::length).max().orElse(0) + 2;
        int width = h.commandSpec().usageMessage().width();
        StringBuilder out = new StringBuilder();
        for (Map.Entry<String, Help> e : subs.entrySet()) {
            UsageMessageSpec u = e.getValue().commandSpec().usageMessage();
            String text = u.header().length > 0 ? u.header()[0] : u.description().length > 0 ? u.description()[0] : "";
            String lead = "  " + e.getKey() + " ".repeat(nameWidth - e.getKey().length());
            List<String> lines = wrap(text, width - lead.length(), width - lead.length() - WRAPPED_INDENT,
                    " ".repeat(lead.length() + WRAPPED_INDENT));
            out.append(lead).append(lines.get(0)).append(System.lineSeparator());
            for (String l : lines.subList(1, lines.size())) {
                out.append(l).append(System.lineSeparator());
            }
        }
        return out.toString();
    }

    /** The synopsis, built by picocli on one line and wrapped at spaces under the command's name. */
    private static String synopsis(Help h) {
        UsageMessageSpec usage = h.commandSpec().usageMessage();
        int width = usage.width();
        String oneLine;
        // Wide enough for any synopsis on one line; picocli lays a line out in a buffer of this width,
        // so a near-infinite one (Integer.MAX_VALUE / 2) took seconds per help text.
        usage.width(SYNOPSIS_ON_ONE_LINE);
        try {
            oneLine = h.synopsis(h.synopsisHeadingLength()).stripTrailing();
        } finally {
            usage.width(width);
        }
        String name = h.commandSpec().qualifiedName();
        int at = oneLine.indexOf(name);
        int indent = at < 0 ? 0 : h.synopsisHeadingLength() + at + name.length() + 1;
        StringBuilder out = new StringBuilder();
        List<String> lines = wrap(oneLine, width - h.synopsisHeadingLength(), width - indent, " ".repeat(indent));
        for (String l : lines) {
            out.append(l).append(System.lineSeparator());
        }
        return out.toString();
    }

    /**
     * @param text one paragraph
     * @param first room on the first line, characters
     * @param rest room on the lines after it (after {@code indent})
     * @param indent what the lines after the first start with
     * @return the lines, broken at spaces; a word longer than the room stays whole
     */
    static List<String> wrap(String text, int first, int rest, String indent) {
        List<String> out = new ArrayList<>();
        StringBuilder line = new StringBuilder();
        int room = first;
        int lead = text.length() - text.stripLeading().length();
        line.append(text, 0, lead);
        boolean empty = true;
        for (String word : text.strip().split(" +")) {
            if (!empty && line.length() + 1 + word.length() > room + (out.isEmpty() ? 0 : indent.length())) {
                out.add(line.toString());
                line.setLength(0);
                line.append(indent);
                room = rest;
                empty = true;
            }
            if (!empty) {
                line.append(' ');
            }
            line.append(word);
            empty = false;
        }
        out.add(line.toString());
        return out;
    }

    /** A table whose wrapping columns break their text at spaces, never inside a word. */
    private static final class SpaceWrappingTable extends TextTable {
        SpaceWrappingTable(Help.ColorScheme scheme, Column[] columns) {
            super(scheme, columns);
        }

        @Override
        public Cell putValue(int row, int col, Text value) {
            Column c = columns()[col];
            if (c.overflow != Column.Overflow.WRAP || value == null || value.plainString().isEmpty()) {
                return super.putValue(row, col, value);
            }
            int room = c.width - c.indent;
            List<String> lines = wrap(value.plainString(), room, room - WRAPPED_INDENT, " ".repeat(WRAPPED_INDENT));
            Cell cell = null;
            int r = row;
            for (int i = 0; i < lines.size(); i++) {
                if (i > 0) {
                    r++;
                    if (r >= rowCount()) {
                        addEmptyRow();
                    }
                }
                cell = super.putValue(r, col, Help.Ansi.OFF.new Text(lines.get(i)));
            }
            return cell;
        }
    }
}
