package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.text.HostileText;
import org.kheperasim.sim.text.Shown;
import org.kheperasim.testfixtures.Cli;

/**
 * Issue 35 item 6, end to end: students whose folder names are formulas, hold a line end or ESC, and
 * whose controller prints and throws control characters and a forged result line. Grade's output,
 * {@code report.txt}, {@code results.csv}, {@code results.json} and {@code index.html} hold no raw
 * control character (the JSON reads back to the names); no
 * CSV cell is a formula; each student is one line of the ranking; the CSV reads back to the names.
 */
class HostileTextGradeTest {
    private static final List<String> STUDENTS = List.of("+1+2", "@SUM(1+1)", "=HYPERLINK(\"x.example\",\"click\")", "-3",
            "line\n   1  mallory   100      100", "esc\u001b[2J\u001b[Hname", "rlo\u202eevil");

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void nothingAStudentWroteReachesTheReportRaw() throws Exception {
        Path subs = dir.resolve("submissions");
        for (String s : STUDENTS) {
            HostileText.forger(subs.resolve(s));
        }
        Path out = dir.resolve("report");
        Cli.Printed p = Cli.main("grade", "--submissions", subs.toString(), "--arenas", "lab", "--seeds", "1", "--seconds",
                "2", "--jobs", "2", "--out", out.toString(), "--no-sandbox", "--wall-limit", "90", "--heap-mb", "128");
        int code = p.code();
        String printed = p.out();
        String progress = p.err();
        // Every student's run threw the same way: grade says so in one line, and exits 1 (item 4).
        assertEquals(1, code, printed + progress);
        assertTrue(progress.contains("every run of this grading failed the same way"), progress);
        HostileText.assertNoRawControl("grade's output", printed);
        HostileText.assertNoRawControl("grade's progress", progress);
        String report = Files.readString(out.resolve("report.txt"));
        String csv = Files.readString(out.resolve("results.csv"));
        HostileText.assertNoRawControl("report.txt", report);
        HostileText.assertNoRawControl("results.csv", csv);
        HostileText.assertNoRawControl("index.html", Files.readString(out.resolve("index.html")));
        HostileText.assertNoRawControl("results.json", Files.readString(out.resolve("results.json")));
        assertEquals(new TreeSet<>(STUDENTS), new TreeSet<>(ReportFiles.read(out.resolve("results.json")).plan().students()));

        // Each student is one line of the ranking: the table runs from its header to the blank line.
        List<String> lines = report.lines().toList();
        int header = lines.indexOf(lines.stream().filter(l -> l.startsWith("rank  student")).findFirst().orElseThrow());
        List<String> table = new ArrayList<>();
        for (int i = header + 1; !lines.get(i).isEmpty() && !lines.get(i).equals("Runs not ok:"); i++) {
            table.add(lines.get(i));
        }
        assertEquals(STUDENTS.size(), table.size(), report);
        for (String s : STUDENTS) {
            assertEquals(1, table.stream().filter(l -> l.contains(" " + Shown.line(s) + " ")).count(), s + " in\n" + report);
        }
        assertFalse(report.contains("\n   1  mallory"), report);

        // No cell a spreadsheet would evaluate; the names read back exactly.
        List<String> rows = csv.lines().skip(1).toList();
        assertEquals(STUDENTS.size(), rows.size(), csv);
        for (String row : rows) {
            String first = row.startsWith("\"") ? row.substring(1) : row;
            assertFalse("=+-@\t\r".indexOf(first.charAt(0)) >= 0, row);
            for (String cell : row.split(",")) {
                String c = cell.startsWith("\"") ? cell.substring(1) : cell;
                assertTrue(c.isEmpty() || "=+@".indexOf(c.charAt(0)) < 0, "a formula cell in " + row);
            }
        }
        Set<String> names = ReportFiles.readCsv(out.resolve("results.csv")).stream().map(RunRecord::student)
                .collect(Collectors.toCollection(TreeSet::new));
        assertEquals(new TreeSet<>(STUDENTS), names);
        assertTrue(csv.contains("\n'+1+2,") && csv.contains("\n'@SUM(1+1),") && csv.contains("\n'-3,"), csv);
        assertTrue(csv.contains("\n\"'=HYPERLINK(\"\"x.example\"\",\"\"click\"\")\","), csv);
        // The numbers the grader writes stay numbers.
        assertTrue(rows.stream().allMatch(r -> r.matches(".*,lab,1,threw,[0-9.]+,100,[0-9.]+,[0-9.]+,Forger,.*")), csv);
    }
}
