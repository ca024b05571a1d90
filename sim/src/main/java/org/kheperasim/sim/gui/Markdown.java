package org.kheperasim.sim.gui;

/**
 * Just enough Markdown to read the manual inside the window: headings, paragraphs, bullet lists,
 * fenced code, tables (shown as preformatted text), inline code and bold.
 */
final class Markdown {
    private Markdown() {
    }

    static String toHtml(String md) {
        StringBuilder out = new StringBuilder("<html><body style='font-family:sans-serif; margin:10px'>");
        String[] lines = md.split("\\R", -1);
        boolean code = false;
        boolean list = false;
        boolean para = false;
        boolean table = false;
        for (String raw : lines) {
            String line = raw;
            if (line.strip().startsWith("```")) {
                if (para) {
                    out.append("</p>");
                    para = false;
                }
                if (list && !code && !raw.startsWith(" ")) {
                    out.append("</ul>");
                    list = false;
                }
                out.append(code ? "</pre>" : "<pre style='background:#f0f0f0'>");
                code = !code;
                continue;
            }
            if (code) {
                out.append(escape(line)).append('\n');
                continue;
            }
            boolean isTable = line.strip().startsWith("|");
            if (table && !isTable) {
                out.append("</pre>");
                table = false;
            }
            if (isTable) {
                if (!table) {
                    out.append("<pre>");
                    table = true;
                }
                if (!line.matches("\\s*\\|[-| :]+\\|\\s*")) {
                    out.append(escape(line)).append('\n');
                }
                continue;
            }
            String t = line.strip();
            boolean bullet = t.startsWith("* ") || t.startsWith("- ") || t.matches("\\d+\\. .*");
            if (list && !bullet && (t.isEmpty() || !raw.startsWith(" "))) {
                out.append("</ul>");
                list = false;
            }
            if (t.isEmpty()) {
                if (para) {
                    out.append("</p>");
                    para = false;
                }
                continue;
            }
            if (t.startsWith("#")) {
                if (para) {
                    out.append("</p>");
                    para = false;
                }
                int level = 0;
                while (level < t.length() && t.charAt(level) == '#') {
                    level++;
                }
                level = StrictMath.min(level, 4);
                out.append("<h").append(level).append('>').append(inline(t.substring(level).strip())).append("</h").append(level).append('>');
                continue;
            }
            if (bullet) {
                if (para) {
                    out.append("</p>");
                    para = false;
                }
                if (!list) {
                    out.append("<ul>");
                    list = true;
                }
                out.append("<li>").append(inline(t.replaceFirst("^(\\* |- |\\d+\\. )", ""))).append("</li>");
                continue;
            }
            if (list && raw.startsWith(" ") && out.toString().endsWith("</li>")) {
                // A bullet's continuation line: part of the same item.
                out.setLength(out.length() - "</li>".length());
                out.append(' ').append(inline(t)).append("</li>");
                continue;
            }
            if (!para && !list) {
                out.append("<p>");
                para = true;
            }
            out.append(inline(t)).append(' ');
        }
        if (code || table) {
            out.append("</pre>");
        }
        if (list) {
            out.append("</ul>");
        }
        if (para) {
            out.append("</p>");
        }
        return out.append("</body></html>").toString();
    }

    private static String inline(String s) {
        String e = escape(s);
        e = e.replaceAll("`([^`]+)`", "<code>$1</code>");
        e = e.replaceAll("\\*\\*([^*]+)\\*\\*", "<b>$1</b>");
        e = e.replaceAll("\\[([^\\]]+)\\]\\([^)]+\\)", "<u>$1</u>");
        return e;
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
