package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.RobotKind;

/**
 * The bundled Braitenberg, unchanged, on each bundled robot in the maze for 60 s: it travels a metre
 * and turns away from walls (fewer wall contacts than the same robot driving straight at the same
 * 48 mm/s, {@link DriveStraight}). It works in mm/s and in a fraction of its robot's proximity scale,
 * so the one class cruises at 48 mm/s on each (6 units of a Khepera, 373 steps/s of an e-puck). The
 * scale is what the robot's sensors read at most ({@code Sensor.getMaxDistValue()}): 1023 on a Khepera,
 * whose sensors saturate; 2976 on the e-puck, whose response tops out at 72 % of its 12-bit 4095. Taken
 * as a fraction of 4095 instead, the e-puck's walls read a quarter as loud and it touched them 2 to 4
 * times over seeds 1 to 6, where driving straight touches once.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class BraitenbergOnEveryRobotTest {

    private static RunResult.RobotResult run(String robot, String controller) {
        Arena maze = ArenaFormat.resolve("maze").withDefaultRobot(RobotKind.of(robot));
        return Simulation.builder().arena(maze).controller(controller).trusted(true).seed(4).seconds(60).run()
                .robots().get(0);
    }

    @ParameterizedTest
    @ValueSource(strings = {"khepera1", "khepera2", "epuck"})
    void itTravelsAMetre(String robot) {
        RunResult.RobotResult b = run(robot, "Braitenberg");
        assertTrue(b.distanceMm() >= 1000, robot + " travelled " + b.distanceMm() + " mm");
    }

    @ParameterizedTest
    @ValueSource(strings = {"khepera1", "khepera2", "epuck"})
    void itTurnsAwayFromWalls(String robot) {
        turnsAwayFromWalls(robot);
    }

    private static void turnsAwayFromWalls(String robot) {
        RunResult.RobotResult b = run(robot, "Braitenberg");
        RunResult.RobotResult straight = run(robot, DriveStraight.class.getName());
        assertTrue(straight.collisions() > 0, robot + " driving straight met no wall: the comparison says nothing");
        assertTrue(b.collisions() < straight.collisions(),
                robot + ": " + b.collisions() + " contacts against " + straight.collisions() + " driving straight");
    }
}
