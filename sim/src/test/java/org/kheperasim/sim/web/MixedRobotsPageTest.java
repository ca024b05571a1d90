package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.RobotKind;
import org.kheperasim.sim.engine.robot.RobotFileWriter;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/** The web page draws each robot with its own body and sensors; a Khepera's entry stays as it was. */
class MixedRobotsPageTest {
    @TempDir
    Path dir;

    @Test
    @SuppressWarnings("unchecked")
    void eachRobotOtherThanAKheperaCarriesItsRadiusAndMounts() throws Exception {
        String text = "khepera-arena 1\nname mixed\nsize 1000 1000\nrobot 250 500 0\nrobot 750 500 180 epuck\n"
                + "wall 0 4 1000 4 8\nwall 0 996 1000 996 8\nwall 4 0 4 1000 8\nwall 996 0 996 1000 8\n";
        Arena arena = ArenaFormat.parse(text, "mixed.arena");
        RunPageRecorder recorder = new RunPageRecorder(arena, null);
        RunResult result = Simulation.builder().arena(arena).controller("Braitenberg").seed(3).seconds(5)
                .listener(recorder, RunPageRecorder.PERIOD_MILLIS).console(l -> { }).run();
        Path page = dir.resolve("mixed.html");
        RunPage.write(recorder, RunOutcome.of(result), page);
        List<Map<String, Object>> robots = (List<Map<String, Object>>) RunPageTest.run(page).get("robots");
        assertFalse(robots.get(0).containsKey("radius"), "a Khepera is drawn by the page's model");
        assertEquals(35.0, ((Number) robots.get(1).get("radius")).doubleValue());
        assertEquals(8, ((List<?>) robots.get(1).get("mounts")).size());
    }

    @Test
    void aRobotWithThreeSensorsIsRecorded() throws Exception {
        String tri = RobotFileWriter.write(RobotTypes.KHEPERA1).replace("name: khepera1", "name: tri");
        int from = tri.indexOf("  - name: RIGHT_45");
        int to = tri.indexOf("proximity:");
        tri = tri.substring(0, from) + tri.substring(to);
        tri = tri.replace("  - name: LEFT_90\n    channel: 0\n    origin: [10, 24, 90]\n", "")
                .replace("channel: 1", "channel: 0").replace("channel: 2", "channel: 1").replace("channel: 3", "channel: 2");
        Path file = dir.resolve("tri.yaml");
        Files.writeString(file, tri);
        Arena lab = ArenaFormat.loadBundled("lab").withDefaultRobot(RobotKind.of(file.toString()));
        assertEquals(3, lab.robotType(0).sensorCount());
        RunPageRecorder recorder = new RunPageRecorder(lab, null);
        RunResult result = Simulation.builder().arena(lab).controller(org.kheperasim.sim.run.DriveStraight.class.getName())
                .trusted(true).seed(3).seconds(5).listener(recorder, RunPageRecorder.PERIOD_MILLIS).console(l -> { }).run();
        Path page = dir.resolve("tri.html");
        RunPage.write(recorder, RunOutcome.of(result), page);
        List<Map<String, Object>> robots = (List<Map<String, Object>>) RunPageTest.run(page).get("robots");
        assertEquals(3, ((List<?>) robots.get(0).get("mounts")).size());
    }
}
