package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.SettingsFile;

/** The manual is inside the application; settings profiles round-trip; the settings table covers the catalogue. */
class HelpAndSettingsTest {

    @Test
    void everyManualPageIsInsideTheApplicationAndRendersAsHtml() {
        for (String page : HelpDialog.PAGES) {
            String text = HelpDialog.text(page);
            assertNotNull(text, page + " must be copied from docs/ into the jar");
            String html = Markdown.toHtml(text);
            assertTrue(html.contains("<h1>"), page);
        }
        String html = Markdown.toHtml("## A <b>\n\n1. one\n2. two\n\n| key | what |\n|---|---|\n| F5 | start |\n\n"
                + "See [the model](simulation-model.md) and `x`.\n\n```\na & b\n```\n");
        assertTrue(html.contains("<h2>A &lt;b&gt;</h2>"), "headings, raw HTML shown as text: " + html);
        assertTrue(html.contains("<ol>") && html.contains("<li>two</li>"), "numbered lists are numbered: " + html);
        assertTrue(html.contains("<table>") && html.contains("<th>key</th>") && html.contains("<td>F5</td>"),
                "tables are tables, not pipes: " + html);
        assertTrue(html.contains("<a href=\"simulation-model.md\">the model</a>"), "links are links: " + html);
        assertTrue(html.contains("<pre><code>a &amp; b"), "code blocks, escaped: " + html);
    }

    @Test
    void theHelpListsEveryPageOfTheDocsFolder() throws java.io.IOException {
        Path docs = Path.of(System.getProperty("kheperasim.repoRoot", ".."), "docs");
        java.util.Set<String> pages;
        try (var files = java.nio.file.Files.list(docs)) {
            pages = files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".md"))
                    .collect(java.util.stream.Collectors.toCollection(java.util.TreeSet::new));
        }
        assertEquals(pages, new java.util.TreeSet<>(HelpDialog.PAGES), "Help > Manual lists exactly the pages in docs/");
    }

    @Test
    void aProfileRoundTripsAndABadLineIsNamed(@TempDir Path dir) {
        Settings s = Settings.defaults().with("prox.3.dead", "true").with("motor.left.calibration", "0.8").with("link.baud", "9600");
        Path file = dir.resolve("worn.settings");
        SettingsFile.save(s, file);
        assertEquals(s, SettingsFile.load(file));
        assertEquals(dir.resolve("maze.settings"), SettingsFile.besideArena(dir.resolve("maze.arena")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SettingsFile.parse("# c\nprox.3.gain=11\n", "p"));
        assertTrue(e.getMessage().startsWith("p:2: "), e.getMessage());
    }

    @Test
    void theSettingsTableShowsEveryKeyAndEditsThroughSettingsChecks() {
        SettingsDialog.Model m = new SettingsDialog.Model(Settings.defaults());
        assertEquals(Settings.catalogue().size(), m.getRowCount());
        int row = -1;
        for (int i = 0; i < m.getRowCount(); i++) {
            if (m.getValueAt(i, 0).equals("prox.5.gain")) {
                row = i;
            }
        }
        m.setValueAt("0.5", row, 1);
        assertEquals(Settings.defaults().with("prox.5.gain", "0.5"), m.settings());
        m.setValueAt("abc", row, 1);
        assertThrows(IllegalArgumentException.class, m::settings);
    }
}
