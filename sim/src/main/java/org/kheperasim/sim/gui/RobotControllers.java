package org.kheperasim.sim.gui;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.RobotSetup;

/**
 * Which controller each robot of the window's arena runs: the one chosen in the controller box,
 * except for the robots given one of their own (Controller &gt; Give the selected robot this
 * controller).
 */
final class RobotControllers {
    private final Map<Integer, String> own = new TreeMap<>();

    /** Robot {@code index} runs {@code controller} from the next Start. */
    void assign(int index, String controller) {
        own.put(index, controller);
    }

    /** Every robot runs the chosen controller again. */
    void clear() {
        own.clear();
    }

    /** @return true when no robot has a controller of its own */
    boolean none() {
        return own.isEmpty();
    }

    /**
     * @param robots how many robots the arena has
     * @param chosen the controller in the controller box
     * @param settings the run's settings
     * @return one setup per robot
     */
    List<RobotSetup> setups(int robots, String chosen, Settings settings) {
        List<RobotSetup> out = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            out.add(new RobotSetup(own.getOrDefault(i, chosen), settings));
        }
        return out;
    }

    /** @return e.g. "robot 1 runs WallFollower", for the console; empty when none has its own */
    String describe(int robots) {
        List<String> parts = new ArrayList<>();
        own.forEach((i, c) -> {
            if (i < robots) {
                parts.add("robot " + i + " runs " + c);
            }
        });
        return String.join(", ", parts);
    }
}
