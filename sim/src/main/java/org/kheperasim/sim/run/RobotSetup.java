package org.kheperasim.sim.run;

import java.util.Objects;
import org.kheperasim.sim.engine.Settings;

/**
 * What one robot of a run is given: its controller and its settings (one robot with a worn motor,
 * another with noisier sensors, each with a controller of its own).
 *
 * @param controller a bundled controller or a class on the classpath
 * @param settings the robot's sensor, motor and link settings
 */
public record RobotSetup(String controller, Settings settings) {
    public RobotSetup {
        Objects.requireNonNull(controller, "no controller given");
        Objects.requireNonNull(settings, "no settings given");
    }
}
