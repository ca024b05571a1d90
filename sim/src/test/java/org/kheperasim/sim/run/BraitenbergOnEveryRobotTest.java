package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Disabled;
import org.junit.jupiter.api.Test;
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
 * so the one class cruises at 48 mm/s on each (6 units of a Khepera, 373 steps/s of an e-puck).
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
    @ValueSource(strings = {"khepera1", "khepera2"})
    void itTurnsAwayFromWalls(String robot) {
        turnsAwayFromWalls(robot);
    }

    /**
     * Not yet on the e-puck: over seeds 1 to 6 it touches a wall 2 to 4 times (seed 4: 4) where driving
     * straight touches once and stays. Its response (Enki's, epuck.yaml) tops out at 2966 + 10 counts, 72 %
     * of its 4095 scale, and falls faster: as a fraction of the scale a wall 20 mm from a sensor reads about
     * 0.15 on the e-puck, 0.6 on a Khepera, so every weighted sum turns it a quarter as hard. The front
     * counts as blocked at 49 % of the scale, 2001 counts, which the e-puck reads about 8.5 mm from a front
     * sensor, 5 mm from its body's edge (they sit 31 mm out on a 35 mm body): one 100 ms decision at
     * 48 mm/s (a Khepera: 24 mm from the sensor, 22 from its edge). Taking the scale as the response's top
     * (2976) instead, it touches no wall on seeds 1 to 4; so does a threshold of 200 on seed 4.
     */
    @Test
    @Disabled("issue 36: the e-puck's readings fill 72 % of its 4095 scale; see the Javadoc")
    void onTheEpuckItTurnsAwayFromWallsToo() {
        turnsAwayFromWalls("epuck");
    }

    private static void turnsAwayFromWalls(String robot) {
        RunResult.RobotResult b = run(robot, "Braitenberg");
        RunResult.RobotResult straight = run(robot, DriveStraight.class.getName());
        assertTrue(straight.collisions() > 0, robot + " driving straight met no wall: the comparison says nothing");
        assertTrue(b.collisions() < straight.collisions(),
                robot + ": " + b.collisions() + " contacts against " + straight.collisions() + " driving straight");
    }
}
