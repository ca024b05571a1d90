package org.kheperasim.sim.grade;

import java.util.List;
import java.util.Map;
import org.kheperasim.sim.text.Shown;

/**
 * The report as one HTML page: per arena the ranking, with each seed's score linked to its run's page,
 * then every run with its picture, which links to the page that replays it.
 */
final class HtmlReport {
    private HtmlReport() {
    }

    static String of(ReportFiles.Report report) {
        StringBuilder sb = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                + "<title>Grade report</title>\n<style>\n"
                + "body{font-family:sans-serif;margin:1.5em;color:#222}\n"
                + "table{border-collapse:collapse;margin-bottom:1em}td,th{border:1px solid #ccc;padding:3px"
                + " 8px;text-align:left}\n.ok{color:#176f2c}.bad{color:#b01c1c;font-weight:bold}\n"
                + ".runs{display:flex;flex-wrap:wrap;gap:10px}.run{border:1px solid"
                + " #ccc;padding:6px;width:250px;font-size:90%}\n.run"
                + " img{width:240px;height:auto;display:block}.detail{color:#555;word-wrap:break-word}\n"
                + "</style></head><body>\n<h1>Grade report</h1>\n");
        sb.append("<p>").append(report.plan().students().size()).append(" submissions &times; ")
                .append(report.plan().arenas().size()).append(" arenas &times; ").append(report.plan().seeds())
                .append(" seeds = ").append(report.runs().size()).append(" runs")
                .append(report.shard().n() > 1 ? " (shard " + report.shard() + ")" : "")
                .append("; ").append(esc(TextTable.madeIn(report.runs())))
                .append(". Also as <a href=\"results.csv\">CSV</a> and <a href=\"results.json\">JSON</a>.</p>\n")
                .append("<p>").append(esc(Ranking.RULE)).append("</p>\n");
        for (Map.Entry<String, List<Ranking.Entry>> e : Ranking.of(report.runs()).entrySet()) {
            sb.append("<h2>Arena ").append(esc(e.getKey())).append("</h2>\n<table><tr><th>rank</th><th>student</th>"
                    + "<th>mean score %</th><th>mean points</th><th>score % by seed</th></tr>\n");
            for (Ranking.Entry x : e.getValue()) {
                sb.append("<tr><td>").append(x.ranked() ? Integer.toString(x.rank()) : "&ndash;").append("</td><td>")
                        .append(esc(x.student())).append("</td><td>")
                        .append(ReportFiles.num(x.meanPercent())).append("</td><td>")
                        .append(ReportFiles.num(x.meanPoints()))
                        .append("</td><td>");
                for (int i = 0; i < x.runs().size(); i++) {
                    RunRecord r = x.runs().get(i);
                    String tag = r.page().isEmpty() ? "span" : "a";
                    sb.append(i > 0 ? " | " : "").append('<').append(tag)
                            .append(r.page().isEmpty() ? "" : " href=\"" + esc(r.page()) + "\"").append(" class=\"")
                            .append(r.status() == RunStatus.OK ? "ok" : "bad").append("\" title=\"seed ")
                            .append(r.seed())
                            .append(r.detail().isEmpty() ? "" : ": " + esc(r.detail())).append("\">")
                            .append(esc(TextTable.seed(r)))
                            .append("</").append(tag).append('>');
                }
                sb.append("</td></tr>\n");
            }
            sb.append("</table>\n<div class=\"runs\">\n");
            for (Ranking.Entry x : e.getValue()) {
                for (RunRecord r : x.runs()) {
                    sb.append("<div class=\"run\">");
                    if (!r.picture().isEmpty()) {
                        String img = "<img src=\"" + esc(r.picture()) + "\" alt=\"trajectory of "
                                + esc(r.student()) + " seed "
                                + r.seed() + "\">";
                        sb.append(r.page().isEmpty() ? img
                                : "<a href=\"" + esc(r.page()) + "\" title=\"watch the run\">" + img
                                + "</a>");
                    }
                    sb.append("<b>").append(esc(r.student())).append("</b> seed ").append(r.seed()).append("<br>")
                            .append(status(r)).append(" &middot; ").append(ReportFiles.num(r.points())).append('/')
                            .append(ReportFiles.num(r.max())).append(" points")
                            .append(r.madeIn().equals(RunRecord.NO_SANDBOX) ? " &middot; <b>no sandbox</b>" : "")
                            .append(r.page().isEmpty() ? "" : " &middot; <a href=\"" + esc(r.page()) + "\">watch</a>")
                            .append("<br><span class=\"detail\">")
                            .append(esc(r.detail())).append("</span></div>\n");
                }
            }
            sb.append("</div>\n");
        }
        return sb.append("</body></html>\n").toString();
    }

    private static String status(RunRecord r) {
        return "<span class=\"" + (r.status() == RunStatus.OK ? "ok" : "bad") + "\">"
                + esc(r.status().label()) + "</span>";
    }

    /**
     * @return {@code s} for HTML text or an attribute, its control characters escaped as {@link Shown#line} escapes
     *     them
     */
    static String esc(String s) {
        return Shown.line(s).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
