package org.kheperasim.sim.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.grade.JsonValues;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code grade junit}: a Surefire report folder (the course's hidden tests) as the platforms' results:
 * a test per test case with its points when it passed, the failure's message and the student's line
 * otherwise, hidden when asked; no report is not gradable; a report with a DOCTYPE is refused (no
 * entity of a student's build is expanded).
 */
class JunitReportsTest {
    private static final Path REPORTS = Path.of("src", "test", "resources", "platforms", "surefire");

    @TempDir
    Path dir;

    @Test
    @SuppressWarnings("unchecked")
    void eachTestCaseIsATestWithItsPoints() throws Exception {
        Cli.Printed p = Cli.main("grade", "junit", "--reports", REPORTS.toString(), "--format", "gradescope,classroom",
                "--points", "2", "--hidden", "--out", dir.toString());
        assertEquals(0, p.code(), p.err());
        Map<String, Object> gs = (Map<String, Object>) JsonValues.parse(Files.readString(dir.resolve(
                "gradescope/submission/results.json")));
        List<Map<String, Object>> tests = (List<Map<String, Object>>) gs.get("tests");
        assertEquals(List.of("GradingTest.runsWithoutFaultsAndNeverTouchesAWall(long)[1]", "GradingTest.scoresAtLeastHalfThePoints",
                "GradingTest.reachesTheGoal", "GradingTest.bonus"), tests.stream().map(t -> t.get("name")).toList());
        assertEquals(List.of(2.0, 0.0, 0.0, 0.0), tests.stream().map(t -> ((Number) t.get("score")).doubleValue()).toList());
        assertEquals(List.of("hidden"), tests.stream().map(t -> t.get("visibility")).distinct().toList());
        assertEquals(2.0, ((Number) gs.get("score")).doubleValue());
        String failure = (String) tests.get(1).get("output");
        assertTrue(failure.startsWith("failed: expected a score of at least 50 points; the run scored 36"), failure);
        assertTrue(failure.contains("GradingTest.java:27"), failure);
        assertTrue(((String) tests.get(2).get("output")).contains("MyController.java:14"));
        assertTrue(((String) tests.get(3).get("output")).startsWith("skipped: not this term"));
        Map<String, Object> cls = (Map<String, Object>) JsonValues.parse(Files.readString(dir.resolve(
                "classroom/submission/result.json")));
        assertEquals(8.0, ((Number) cls.get("max_score")).doubleValue());
        assertEquals("error", cls.get("status"), "a test case in error makes the runner an error, as the reporter reads it");
    }

    @Test
    @SuppressWarnings("unchecked")
    void noReportIsNotGradable() throws Exception {
        Cli.Printed p = Cli.main("grade", "junit", "--reports", dir.resolve("none").toString(), "--format", "prairielearn",
                "--out", dir.toString());
        assertEquals(0, p.code(), p.err());
        Map<String, Object> pl = (Map<String, Object>) JsonValues.parse(Files.readString(dir.resolve(
                "prairielearn/submission/results.json")));
        assertEquals(false, pl.get("gradable"));
        assertFalse(pl.containsKey("score"));
        assertTrue(((List<String>) pl.get("format_errors")).get(0).contains("the tests did not run"));
    }

    @Test
    void aReportWithADoctypeIsRefused() throws Exception {
        Path reports = Files.createDirectories(dir.resolve("evil"));
        Files.writeString(reports.resolve("TEST-x.xml"), "<?xml version=\"1.0\"?><!DOCTYPE t [<!ENTITY e SYSTEM"
                + " \"file:///etc/passwd\">]><testsuite><testcase name=\"&e;\" classname=\"X\"/></testsuite>");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> JunitReports.read(reports, "s", 1, false));
        assertTrue(e.getMessage().contains("is not a JUnit XML report"), e.getMessage());
    }
}
