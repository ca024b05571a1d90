package org.kheperasim.sim.grade.platform;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * GitHub Classroom's runner result, the JSON a step hands the {@code autograding-grading-reporter} as its
 * base64 {@code result} output: {@code {version: 1, status, max_score, tests: [{name, status, score,
 * message, test_code, filename, line_no, execution_time}]}}. The reporter adds up {@code tests[].score}
 * against {@code max_score}, so each run gives its own points (the command grader's all or nothing is
 * gone). A failure names the student's file and line in {@code filename} and {@code line_no}. A
 * submission that cannot be graded is {@code "status": "error"}. Classroom shows every test, so a
 * hidden arena's test keeps only its points ({@link PlatformTest#masked}).
 */
final class ClassroomFormat {
    /** The student's frame in a failure's detail: {@code (Thrower.java:9)}. */
    private static final Pattern FRAME = Pattern.compile("\\(([A-Za-z0-9_$]+\\.java):(\\d{1,7})\\)");

    private ClassroomFormat() {
    }

    /** @param r a submission's result @return its runner result, JSON */
    static String of(PlatformResult r) {
        Map<String, Object> top = new LinkedHashMap<>();
        top.put("version", 1);
        List<Object> tests = new ArrayList<>();
        String status;
        if (!r.gradable()) {
            status = "error";
            tests.add(test("compiles and loads", "error", 0, "not gradable: " + r.problem()));
        } else {
            boolean all = true;
            boolean error = false;
            for (PlatformTest whole : r.tests()) {
                String s = whole.passed() ? "pass" : "error".equals(whole.status()) ? "error" : "fail";
                PlatformTest p = whole.masked();
                all &= p.passed();
                error |= "error".equals(s);
                tests.add(test(p.name(), s, p.score(), p.output()));
            }
            status = all ? "pass" : error ? "error" : "fail";
        }
        top.put("status", status);
        top.put("max_score", r.max());
        top.put("tests", tests);
        return JsonText.of(top);
    }

    private static Map<String, Object> test(String name, String status, double score, String message) {
        Map<String, Object> t = new LinkedHashMap<>();
        t.put("name", name);
        t.put("status", status);
        t.put("score", score);
        t.put("message", message);
        t.put("test_code", "");
        Matcher m = FRAME.matcher(message);
        t.put("filename", m.find() ? m.group(1) : "");
        t.put("line_no", m.find(0) ? Integer.parseInt(m.group(2)) : 0);
        t.put("execution_time", "");
        return t;
    }
}
