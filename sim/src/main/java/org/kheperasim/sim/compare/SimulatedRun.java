package org.kheperasim.sim.compare;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.RobotKind;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.run.Simulation;

/** Runs a controller in the simulator from a start pose and keeps robot 0's samples as a {@link Track}. */
public final class SimulatedRun {
    private SimulatedRun() {
    }

    /**
     * @param arena the arena
     * @param start robot 0's start pose (null: the arena's)
     * @param type robot 0's type (null: the arena's)
     * @param controller the controller's name
     * @param settings the settings
     * @param seed the seed
     * @param seconds how long
     * @param periodMillis how often a sample is kept
     * @return robot 0's samples
     */
    public static Track run(Arena arena, Pose start, RobotType type, String controller, Settings settings, long seed,
            double seconds, long periodMillis) {
        List<Pose> poses = new ArrayList<>(arena.robots());
        List<RobotKind> kinds = new ArrayList<>(arena.robotKinds());
        if (start != null) {
            poses.set(0, start);
        }
        if (type != null) {
            kinds.set(0, new RobotKind(type.name(), type));
        }
        Arena a = new Arena(arena.name(), arena.width(), arena.height(), poses, arena.walls(),
                arena.lights(), arena.caps(),
                arena.regions(), arena.assignment(), kinds);
        List<Track.Point> points = new ArrayList<>();
        Simulation.builder().arena(a).controller(controller).settings(settings).seed(seed).seconds(seconds)
                .listener(snapshot -> {
                    RobotView r = snapshot.robots().get(0);
                    points.add(new Track.Point(snapshot.timeNanos() / 1e9, r.proximity(), r.encoderLeft(),
                            r.encoderRight()));
                }, periodMillis).run();
        return new Track(points);
    }
}
