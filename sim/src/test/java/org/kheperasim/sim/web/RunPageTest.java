package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.grade.JsonValues;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;
import org.kheperasim.testfixtures.Arenas;

/** A run's web page as a file: its size, what it says about the run, and that it needs nothing from outside. */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunPageTest {
    @TempDir
    Path dir;

    private Path trace(String name, Arena arena, String controller, double seconds) {
        Path trace = dir.resolve(name + ".trace");
        Simulation.builder().arena(arena).controller(controller).seed(1).seconds(seconds).trace(trace).console(l -> { }).run();
        return trace;
    }

    /** The page's description of its run. */
    @SuppressWarnings("unchecked")
    static Map<String, Object> run(Path page) throws Exception {
        String html = Files.readString(page, StandardCharsets.UTF_8);
        int from = html.indexOf("var RUN = ") + "var RUN = ".length();
        int to = html.indexOf(";\nvar SAMPLES = ", from);
        return (Map<String, Object>) JsonValues.parse(html.substring(from, to));
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> scores(Map<String, Object> run) {
        return (List<Map<String, Object>>) run.get("scores");
    }

    @Test
    void aSixHundredSecondRunFitsInTwoHundredKilobytes() throws Exception {
        RunPage.Written maze = RunPage.write(trace("maze", ArenaFormat.loadBundled("maze"), "WallFollower", 600), dir.resolve("maze.html"));
        assertTrue(maze.bytes() < 200_000, maze.toString());
        assertEquals(50, maze.poseEveryMs(), "one robot: every sample kept");
        assertEquals(50, maze.sensorsEveryMs(), "one robot: every sensor value kept");
        assertEquals(600.0, maze.seconds());
        RunPage.Written three = RunPage.write(trace("three", Arenas.THREE, "Braitenberg", 600), Arenas.THREE, RunOutcome.none(),
                dir.resolve("three.html"));
        assertTrue(three.bytes() < 200_000, three.toString());
        assertEquals(3, three.robots());
        assertEquals(50, three.poseEveryMs(), "three robots: every pose kept");
        assertTrue(three.sensorsEveryMs() > 50 && three.sensorsEveryMs() <= 250, "three robots: sensor values thinned a little: " + three);
        Map<String, Object> run = run(three.file());
        assertEquals(three.sensorsEveryMs() / 50.0, run.get("sensorStride"));
        System.out.printf("page of a 600 s run: maze, 1 robot %d bytes; three, 3 robots %d bytes (sensor values every %d ms)%n",
                maze.bytes(), three.bytes(), three.sensorsEveryMs());
    }

    @Test
    void theScoreAtTheEndIsTheRunsScoreAndGrowsOnTheWay() throws Exception {
        Arena maze = ArenaFormat.loadBundled("maze");
        RunPageRecorder recorder = new RunPageRecorder(maze, null);
        RunResult result = Simulation.builder().arena(maze).controller("WallFollower").seed(1).seconds(120)
                .listener(recorder, RunPageRecorder.PERIOD_MILLIS).console(recorder::console).run();
        Path page = dir.resolve("maze.html");
        RunPage.write(recorder, RunOutcome.of(result), page);
        List<Map<String, Object>> scores = scores(run(page));
        Score expected = Score.of(maze, RunFacts.of(result));
        Map<String, Object> last = scores.get(scores.size() - 1);
        assertEquals(Score.number(expected.points()), last.get("points"));
        assertEquals(Boolean.FALSE, last.get("pending"));
        double before = -1;
        for (Map<String, Object> s : scores) {
            double p = Double.parseDouble((String) s.get("points"));
            assertTrue(p > before, "the maze's visits only add up: " + scores);
            before = p;
        }
        assertTrue(scores.size() >= 3, "the score changed on the way: " + scores);
        // The run's own entry times: each change falls at a region's first entry.
        for (Map<String, Object> s : scores.subList(1, scores.size())) {
            double t = (Double) s.get("t") / 1000;
            assertTrue(result.first().regionsEntered().values().stream().anyMatch(at -> at <= t && at > t - 0.05),
                    "a change at " + t + " s with no region entered just then: " + result.first().regionsEntered());
        }
        // From the trace alone the regions count from the samples: the same score at the end.
        Path trace = trace("maze", maze, "WallFollower", 120);
        Path fromTrace = dir.resolve("maze-trace.html");
        RunPage.write(trace, fromTrace);
        List<Map<String, Object>> traced = scores(run(fromTrace));
        assertEquals(last.get("points"), traced.get(traced.size() - 1).get("points"));
    }

    @Test
    void floorCoverageIsPendingUntilTheRunsOwnFactsAreKnown() throws Exception {
        Arena lab = ArenaFormat.loadBundled("lab");
        RunPageRecorder recorder = new RunPageRecorder(lab, null);
        Path trace = dir.resolve("lab.trace");
        RunResult result = Simulation.builder().arena(lab).controller("Braitenberg").seed(3).seconds(60).trace(trace)
                .listener(recorder, RunPageRecorder.PERIOD_MILLIS).console(l -> { }).run();
        Path fromTrace = dir.resolve("trace.html");
        RunPage.write(trace, fromTrace);
        Map<String, Object> run = run(fromTrace);
        List<Map<String, Object>> scores = scores(run);
        assertEquals(Boolean.TRUE, scores.get(scores.size() - 1).get("pending"), "a trace does not record the floor covered");
        assertEquals(Boolean.FALSE, run.get("coverageAtEnd"));
        Path fromRun = dir.resolve("run.html");
        RunPage.write(recorder, RunOutcome.of(result), fromRun);
        List<Map<String, Object>> exact = scores(run(fromRun));
        Map<String, Object> last = exact.get(exact.size() - 1);
        assertEquals(Boolean.FALSE, last.get("pending"));
        assertEquals(Score.number(Score.of(lab, RunFacts.of(result)).points()), last.get("points"));
        assertTrue(Double.parseDouble((String) last.get("points")) > 0, "the run covered some floor: " + last);
    }

    @Test
    void capsCarriedAcrossAreScoredAsTheRunScoresThem() throws Exception {
        Arena rooms = ArenaFormat.loadBundled("two-rooms");
        Path trace = dir.resolve("caps.trace");
        RunResult result = Simulation.builder().arena(rooms).controller("CapGatherer").seed(1).seconds(500).trace(trace)
                .console(l -> { }).run();
        Path page = dir.resolve("caps.html");
        RunPage.write(trace, page);
        Map<String, Object> run = run(page);
        assertTrue((Double) run.get("capMoves") > 10, "caps moved: " + run.get("capMoves"));
        List<Map<String, Object>> scores = scores(run);
        assertEquals(Score.number(Score.of(rooms, RunFacts.of(result)).points()), scores.get(scores.size() - 1).get("points"));
    }

    @Test
    void thePageNeedsNothingFromOutside() throws Exception {
        Path page = dir.resolve("lab.html");
        RunPage.write(trace("lab", ArenaFormat.loadBundled("lab"), "Braitenberg", 20), page);
        String html = Files.readString(page, StandardCharsets.UTF_8);
        for (String outside : new String[] {"http://", "https://", " src=", "<link", "@import", "fetch(", "XMLHttpRequest",
            "import(", "url("}) {
            assertFalse(html.contains(outside), "the page reaches outside with " + outside);
        }
    }

    @Test
    void noTextFromTheRunCanEndTheScript() throws Exception {
        Path trace = trace("lab", ArenaFormat.loadBundled("lab"), "Braitenberg", 5);
        String evil = "</script><script>alert(1)</script><!--";
        Path page = dir.resolve("evil.html");
        RunPage.write(trace, ArenaFormat.loadBundled("lab"), new RunOutcome("<b>" + evil, List.of(
                new RunOutcome.Failure(0, 2.5, "failed", evil)), null), page);
        String html = Files.readString(page, StandardCharsets.UTF_8);
        assertEquals(1, html.split("</script>", -1).length - 1, "only the page's own script ends");
        assertTrue(html.contains("<title>&lt;b&gt;&lt;/script&gt;&lt;script&gt;alert(1)"), "the title is text, not markup");
        Map<String, Object> run = run(page);
        assertEquals("<b>" + evil, run.get("title"));
        assertEquals(2500.0, ((Map<?, ?>) ((List<?>) run.get("failures")).get(0)).get("t"));
    }

    @Test
    void theSameRunGivesTheSameBytes() throws Exception {
        Path trace = trace("maze", ArenaFormat.loadBundled("maze"), "WallFollower", 30);
        RunPage.write(trace, dir.resolve("a.html"));
        RunPage.write(trace, dir.resolve("b.html"));
        assertArrayEquals(Files.readAllBytes(dir.resolve("a.html")), Files.readAllBytes(dir.resolve("b.html")));
    }

    @Test
    void aPageGoesToAFileInAFolderThatExists() {
        Path trace = trace("lab", ArenaFormat.loadBundled("lab"), "Braitenberg", 2);
        IllegalArgumentException folder = assertThrows(IllegalArgumentException.class, () -> RunPage.write(trace, dir));
        assertTrue(folder.getMessage().contains("it is a folder; give a file name such as"), folder.getMessage());
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> RunPage.write(trace, dir.resolve("no/such/run.html")));
        assertTrue(missing.getMessage().contains("does not exist; create it or give another path"), missing.getMessage());
        ReplayFiles.open(trace);
    }
}
