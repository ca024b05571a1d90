package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.RobotKind;

/** A robot file written from scratch (three sensors, another wheel base), not bundled, runs headless. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class FromScratchRobotTest {
    static final String TRI = """
            name: tri
            source: a round robot with three sensors, made up for this test
            dialect: khepera1
            turrets: []
            footprint:
              type: circle
              radius: 30
            drive:
              wheel_base: 45
              speed_unit: 8
              max_speed: 127
              encoder_resolution: 0.08
              motor_period: 10
              noise_period: 50
              move_speed: 20
              acceleration: 64
            sensors:
              - name: LEFT
                channel: 0
                origin: [20, 20, 60]
              - name: FRONT
                channel: 1
                origin: [29, 0, 0]
              - name: RIGHT
                channel: 2
                origin: [20, -20, -60]
            proximity:
              response: curve
              angles: [0, 15]
              weights: [1, 0.7]
              distances: [0, 20, 40, 60]
              values: [1023, 600, 130, 0]
              offset: 15
              noise_std_dev: 3
              noise_relative: 0.03
              max_reading: 1023
            light:
              dark: 480
              bright: 20
              noise_relative: 0.01
            """;

    @Test
    void aThreeSensorRobotRunsAControllerWrittenForAnyRobot(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("tri.yaml");
        Files.writeString(file, TRI);
        Arena maze = ArenaFormat.resolve("maze").withDefaultRobot(RobotKind.of(file.toString()));
        assertEquals(3, maze.robotType(0).sensorCount());
        RunResult.RobotResult r = Simulation.builder().arena(maze).controller(AnyRobotAvoider.class.getName()).trusted(true)
                .seed(2).seconds(60).run().robots().get(0);
        assertTrue(r.distanceMm() > 1000, "travelled " + r.distanceMm() + " mm");
        assertTrue(r.failure() == null || r.failure().isEmpty(), String.valueOf(r.failure()));
    }

    @Test
    void aControllerWrittenForTheKheperaIsRefusedWhereItReadsASensorTheRobotLacks(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("tri.yaml");
        Files.writeString(file, TRI);
        Arena maze = ArenaFormat.resolve("maze").withDefaultRobot(RobotKind.of(file.toString()));
        RunResult.RobotResult r = Simulation.builder().arena(maze).controller("Braitenberg").seed(2).seconds(5).run().robots().get(0);
        assertTrue(String.valueOf(r.failure()).contains("this robot (tri) has 3 sensors"), r.status() + ": " + r.failure());
    }
}
