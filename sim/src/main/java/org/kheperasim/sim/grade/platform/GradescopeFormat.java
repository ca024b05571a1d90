package org.kheperasim.sim.grade.platform;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Gradescope's {@code /autograder/results/results.json} (its autograder specification, {@code docs/specs.md}
 * of {@code gradescope/autograder_samples}): the score, the execution time, a line for the submission,
 * one test per run with its {@code score}, {@code max_score}, {@code name}, {@code number}, {@code output},
 * {@code tags} and {@code visibility} ({@code hidden} for a hidden arena), and a {@code leaderboard} of
 * the visible arenas' mean percent. Gradescope knows no "not gradable": such a submission gets one test,
 * "compiles and loads", with 0 of all the points and the reason, and {@code extra_data.gradable} false.
 * Gradescope's output takes no pictures.
 */
final class GradescopeFormat {
    /** The visibility of a hidden arena's tests: never shown to students. */
    static final String HIDDEN = "hidden";

    private GradescopeFormat() {
    }

    /**
     * @param r              a submission's result
     * @param executionSeconds the grading's real seconds, for {@code execution_time}
     * @return its {@code results.json}
     */
    static String of(PlatformResult r, long executionSeconds) {
        Map<String, Object> top = new LinkedHashMap<>();
        top.put("score", r.gradable() ? r.score() : 0.0);
        top.put("execution_time", executionSeconds);
        top.put("output", r.summary());
        top.put("visibility", "visible");
        top.put("stdout_visibility", HIDDEN);
        top.put("extra_data", Map.of("gradable", r.gradable()));
        List<Object> tests = new ArrayList<>();
        if (!r.gradable()) {
            Map<String, Object> t = new LinkedHashMap<>();
            t.put("score", 0.0);
            t.put("max_score", r.max());
            t.put("name", "compiles and loads");
            t.put("number", "0");
            t.put("output", "not gradable: " + r.problem());
            t.put("tags", List.of("not gradable"));
            t.put("visibility", "visible");
            tests.add(t);
        } else {
            for (PlatformTest p : r.tests()) {
                Map<String, Object> t = new LinkedHashMap<>();
                t.put("score", p.score());
                t.put("max_score", p.max());
                t.put("name", p.name());
                t.put("number", p.number());
                t.put("output", p.output());
                t.put("tags", List.of(p.group().isEmpty() ? "tests" : p.group(), p.status()));
                t.put("visibility", p.hidden() ? HIDDEN : "visible");
                tests.add(t);
            }
        }
        top.put("tests", tests);
        List<Object> board = new ArrayList<>();
        if (r.gradable()) {
            for (PlatformResult.Leader l : r.leaderboard()) {
                Map<String, Object> e = new LinkedHashMap<>();
                e.put("name", l.name());
                e.put("value", l.value());
                e.put("order", "desc");
                board.add(e);
            }
        }
        top.put("leaderboard", board);
        return JsonText.of(top);
    }
}
