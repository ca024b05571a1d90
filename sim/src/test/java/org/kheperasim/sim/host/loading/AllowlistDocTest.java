package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.host.loading.AllowlistEntry.Kind;
import org.kheperasim.sim.host.loading.AllowlistEntry.MemberItem;

/**
 * {@code docs/controller-rules.md} shows the allowlist as it is: its tables are rendered from
 * {@code controller-allowlist.txt}, and this test fails when they differ. After changing the list,
 * run it with {@code -Dallowlist.doc.update=true} to rewrite the tables, and review the diff.
 */
class AllowlistDocTest {
    static final String BEGIN = "<!-- allowlist:begin (generated from controller-allowlist.txt by AllowlistDocTest) -->";
    static final String END = "<!-- allowlist:end -->";

    @Test
    void theDocShowsTheListAsItIs() throws IOException {
        Path doc = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("docs/controller-rules.md");
        String text = Files.readString(doc, StandardCharsets.UTF_8);
        int begin = text.indexOf(BEGIN);
        int end = text.indexOf(END);
        assertTrue(begin >= 0 && end > begin, doc + " holds the generated tables between " + BEGIN + " and " + END);
        String shown = text.substring(begin + BEGIN.length(), end);
        String rendered = "\n" + render(Allowlist.bundled()) + "\n";
        if (Boolean.getBoolean("allowlist.doc.update") && !shown.equals(rendered)) {
            Files.writeString(doc, text.substring(0, begin + BEGIN.length()) + rendered + text.substring(end), StandardCharsets.UTF_8);
            return;
        }
        assertEquals(rendered, shown, "docs/controller-rules.md differs from the allowlist: run AllowlistDocTest with"
                + " -Dallowlist.doc.update=true and review the diff");
    }

    /** The list as Markdown: a heading and a table per group, an entry of the file per row. */
    static String render(Allowlist list) {
        StringBuilder out = new StringBuilder();
        AllowlistEntry.Group group = null;
        List<AllowlistEntry> row = new ArrayList<>();
        for (AllowlistEntry e : list.entries()) {
            if (!row.isEmpty() && row.get(0).line() != e.line()) {
                row(out, row);
                row.clear();
            }
            if (!e.group().equals(group)) {
                group = e.group();
                out.append("\n### ").append(group.title()).append("\n\n");
                out.append(group.kind() == Kind.REFUSED ? "| a use of | is refused because |\n|---|---|\n"
                        : "| classes | members | why it is safe |\n|---|---|---|\n");
            }
            row.add(e);
        }
        row(out, row);
        return out.toString().strip();
    }

    private static void row(StringBuilder out, List<AllowlistEntry> entries) {
        AllowlistEntry first = entries.get(0);
        String classes = entries.stream().map(e -> "`" + e.classes().text() + "`").collect(Collectors.joining(", "));
        if (first.classes().mustExtend() != null) {
            classes = "subclasses of `" + first.classes().mustExtend() + "` in " + classes;
        }
        String members = members(first.members());
        String reason = first.reason().replace("|", "\\|");
        if (first.group().kind() == Kind.REFUSED) {
            out.append("| ").append(classes).append(members.isEmpty() ? "" : ": " + members).append(" | ")
                    .append(reason).append(" |\n");
        } else {
            out.append("| ").append(classes).append(" | ").append(members.isEmpty() ? "the type only" : members)
                    .append(" | ").append(reason).append(" |\n");
        }
    }

    /** {@code all except `a`, `b` (but `c(int)`)}, or {@code `a`, `b`}. */
    private static String members(List<MemberItem> items) {
        boolean all = items.stream().anyMatch(m -> m.name().equals("*"));
        String named = items.stream().filter(m -> !m.exclude() && !m.name().equals("*")).map(AllowlistDocTest::member)
                .collect(Collectors.joining(", "));
        if (!all) {
            return named;
        }
        String excluded = items.stream().filter(MemberItem::exclude).map(AllowlistDocTest::member).collect(Collectors.joining(", "));
        return "all" + (excluded.isEmpty() ? "" : " except " + excluded) + (named.isEmpty() ? "" : " (but " + named + ")");
    }

    private static String member(MemberItem m) {
        String name = m.name().equals("<init>") ? "new" : m.name();
        return "`" + name + (m.prefix() ? "*" : "") + (m.parameters() == null ? ""
                : m.parameters().stream().map(p -> p.substring(p.lastIndexOf('.') + 1)).collect(Collectors.joining(", ", "(", ")")))
                + "`";
    }
}
