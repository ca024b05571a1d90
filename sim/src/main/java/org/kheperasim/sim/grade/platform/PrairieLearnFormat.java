package org.kheperasim.sim.grade.platform;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * PrairieLearn's {@code /grade/results/results.json} (its {@code externalGrading.md}, "Grading results"):
 * {@code gradable}, {@code score} in [0, 1], {@code message}, {@code output}, and per run a test with
 * {@code name}, {@code description}, {@code points}, {@code max_points}, {@code message}, {@code output} and its
 * trajectory picture in {@code images} as a base64 data URL, as many pictures as the file's limit of 1 MB
 * leaves room for (the others are left out, and the message says how many). A submission that cannot be
 * graded is {@code "gradable": false} with its {@code format_errors}: PrairieLearn then takes no attempt
 * and gives no points. PrairieLearn shows every test, so a hidden arena's test keeps only its points
 * ({@link PlatformTest#masked}).
 */
final class PrairieLearnFormat {
    /** PrairieLearn's limit on the results file, bytes ("this file should be limited to 1 MB"). */
    static final int LIMIT_BYTES = 1_000_000;

    private PrairieLearnFormat() {
    }

    /**
     * @param r         a submission's result
     * @param reportDir the report folder its pictures are in
     * @return its {@code results.json}, at most {@link #LIMIT_BYTES} bytes
     */
    static String of(PlatformResult r, Path reportDir) {
        Map<String, Object> top = new LinkedHashMap<>();
        if (!r.gradable()) {
            top.put("gradable", false);
            top.put("format_errors", List.of(r.problem()));
            top.put("message", r.summary());
            return JsonText.of(top);
        }
        top.put("gradable", true);
        top.put("score", r.max() > 0 ? StrictMath.min(1.0, r.score() / r.max()) : 0.0);
        top.put("message", r.summary());
        List<Map<String, Object>> tests = new ArrayList<>();
        StringBuilder output = new StringBuilder();
        List<PlatformTest> shown = r.tests().stream().map(PlatformTest::masked).toList();
        for (PlatformTest p : shown) {
            Map<String, Object> t = new LinkedHashMap<>();
            t.put("name", p.name());
            t.put("description", p.hidden() ? "a hidden test" : "a run of the controller in " + p.name());
            t.put("points", p.score());
            t.put("max_points", p.max());
            t.put("message", p.status());
            t.put("output", p.output());
            tests.add(t);
            output.append(p.name()).append(": ").append(p.output().lines().findFirst().orElse("")).append('\n');
        }
        top.put("output", output.toString());
        top.put("tests", tests);
        int room = LIMIT_BYTES - JsonText.of(top).getBytes(StandardCharsets.UTF_8).length - 200;
        int left = 0;
        for (int i = 0; i < shown.size(); i++) {
            PlatformTest p = shown.get(i);
            if (p.picture().isEmpty()) {
                continue;
            }
            String url = dataUrl(reportDir.resolve(p.picture()));
            int cost = url.length() + p.name().length() + 40;
            if (cost > room) {
                left++;
                continue;
            }
            room -= cost;
            tests.get(i).put("images", List.of(Map.of("label", "trajectory, " + p.name(), "url", url)));
        }
        if (left > 0) {
            top.put("message", r.summary()
                    + String.format(Locale.ROOT, "; %d trajectory pictures left out to keep the result"
                    + " within PrairieLearn's 1 MB", left));
        }
        return JsonText.of(top);
    }

    private static String dataUrl(Path png) {
        try {
            return "data:image/png;base64," + Base64.getEncoder().encodeToString(Files.readAllBytes(png));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the picture " + png + ": " + e.getMessage(), e);
        }
    }
}
