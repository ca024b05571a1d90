package org.kheperasim.sim.grade.platform;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * CodeGrade's custom test: what the step prints, a line per run and last the one line CodeGrade reads,
 * {@code {"tag": "points", "points": "S/M"}}. CodeGrade knows no "not gradable" in that line: such a
 * submission prints its reason and {@code 0/M}, and its step exits non-zero (see docs/autograding.md).
 * A hidden arena's lines keep only their points ({@link PlatformTest#masked}); hide the step in
 * CodeGrade to hide the whole.
 */
final class CodeGradeFormat {
    private CodeGradeFormat() {
    }

    /** @param r a submission's result @return what the custom test prints */
    static String of(PlatformResult r) {
        StringBuilder sb = new StringBuilder();
        sb.append(r.summary()).append('\n');
        if (r.gradable()) {
            for (PlatformTest p : r.tests().stream().map(PlatformTest::masked).toList()) {
                sb.append(p.passed() ? "[ok]   " : "[FAIL] ").append(p.name()).append(": ")
                        .append(p.output().replace("\n", " | ")).append('\n');
            }
        }
        Map<String, Object> points = new LinkedHashMap<>();
        points.put("tag", "points");
        points.put("points", org.kheperasim.sim.grade.ReportFiles.num(r.gradable() ? r.score() : 0) + "/"
                + org.kheperasim.sim.grade.ReportFiles.num(r.max()));
        return sb.append(JsonText.line(points)).append('\n').toString();
    }
}
