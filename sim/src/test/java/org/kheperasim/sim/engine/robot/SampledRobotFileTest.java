package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.RobotKind;

/**
 * A robot file can point at a sampled wall table ({@code response: sample}, {@code sample: PATH},
 * relative to the robot file's folder): its response is the table fitted to those readings, the same
 * as {@code prox.profile=sample:PATH} runs; a missing sample file is refused on its line.
 */
class SampledRobotFileTest {
    @TempDir
    Path dir;

    private String robotFile(String samplePath) {
        String k = RobotTypes.bundledText("khepera1");
        int from = k.indexOf("  response: curve");
        int to = k.indexOf("  offset:");
        return k.substring(0, from).replace("name: khepera1", "name: nolfi") + "  response: sample\n  sample: "
                + samplePath + "\n" + k.substring(to);
    }

    @Test
    void aRobotFilePointsAtSampledReadings() throws Exception {
        Path sample = NolfiWallTableTest.sampleFile("khepera-wall.sample");
        Files.copy(sample, dir.resolve("wall.sample"));
        Path file = dir.resolve("nolfi.yaml");
        Files.writeString(file, robotFile("wall.sample"));
        RobotType t = RobotTypes.load(file);
        Response.Table table = assertInstanceOf(Response.Table.class, t.proximity().response());
        Response fitted = RobotTypes.profile(SampleResponses.PREFIX + dir.resolve("wall.sample"));
        assertEquals(RobotFileWriter.write(RobotTypes.KHEPERA1.calibrated("x", 53, 8, 0.08, fitted, 15, 3, 0.03,
                new RobotType.Measured("r", "2026-12-02", java.util.Collections.nCopies(8, 1.0), 1, 1, Double.NaN,
                        Double.NaN))).replaceAll("(?s).*proximity:", "").replaceAll("(?s)  offset.*", ""),
                RobotFileWriter.write(t).replaceAll("(?s).*proximity:", "").replaceAll("(?s)  offset.*", ""),
                "the same table as prox.profile=sample:PATH");
        assertTrue(table.anglesDeg().length > 3, "a table over angle");
        // It runs: Braitenberg in the maze on the sampled robot.
        RunResult r = Simulation.builder().arena(ArenaFormat.resolve("maze").withDefaultRobot(new RobotKind(file.toString(),
                t))).controller("Braitenberg").trusted(true).seed(2).seconds(20).run();
        assertTrue(r.robots().get(0).distanceMm() > 300, r.robots().get(0).distanceMm() + " mm");
    }

    @Test
    void aMissingSampleFileIsRefusedOnItsLine() throws Exception {
        Path file = dir.resolve("nolfi.yaml");
        String text = robotFile("nowhere.sample");
        Files.writeString(file, text);
        RobotFileException e = assertThrows(RobotFileException.class, () -> RobotTypes.load(file));
        int line = text.substring(0, text.indexOf("  sample:")).split("\n", -1).length;
        assertTrue(e.getMessage().startsWith(file + ":" + line + ": sample table "), e.getMessage());
        assertTrue(e.getMessage().contains("does not exist"), e.getMessage());
    }
}
