package org.kheperasim.sim.gui;

import java.util.List;
import org.commonmark.Extension;
import org.commonmark.ext.gfm.tables.TablesExtension;
import org.commonmark.parser.Parser;
import org.commonmark.renderer.html.HtmlRenderer;

/**
 * The manual's Markdown as HTML for the window's help (commonmark-java, with GitHub's tables):
 * headings, lists (bulleted and numbered), tables, code, links. Raw HTML in a page is shown as text.
 */
final class Markdown {
    private static final List<Extension> EXTENSIONS = List.of(TablesExtension.create());
    private static final Parser PARSER = Parser.builder().extensions(EXTENSIONS).build();
    private static final HtmlRenderer RENDERER = HtmlRenderer.builder().extensions(EXTENSIONS).escapeHtml(true).build();
    /** Swing's HTML is HTML 3.2 with a little CSS: borders for tables, a tint for code. */
    private static final String STYLE =
            "<style>body{font-family:sans-serif;margin:10px} pre{background:#f0f0f0;padding:4px}"
            + " code{background:#f0f0f0} table{border-collapse:collapse} th,td{border:1px solid"
            + " #c0c0c0;padding:2px 6px} th{background:#e8e8e8}</style>";

    private Markdown() {
    }

    /** @param md a page of Markdown @return it as an HTML document */
    static String toHtml(String md) {
        return "<html><head>" + STYLE + "</head><body>" + RENDERER.render(PARSER.parse(md)) + "</body></html>";
    }
}
