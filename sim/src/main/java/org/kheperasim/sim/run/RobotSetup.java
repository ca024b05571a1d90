package org.kheperasim.sim.run;

import java.util.Objects;
import org.kheperasim.api.Parameters;
import org.kheperasim.sim.engine.model.Settings;

/**
 * What one robot of a run is given: its controller, its settings (one robot with a worn motor,
 * another with noisier sensors, each with a controller of its own) and the numbers its controller
 * is handed.
 *
 * @param controller a bundled controller or a class on the classpath
 * @param settings the robot's sensor, motor and link settings
 * @param parameters what its controller reads with {@code parameters()}: a weight vector, a genome
 */
public record RobotSetup(String controller, Settings settings, Parameters parameters) {
    public RobotSetup {
        Objects.requireNonNull(controller, "no controller given");
        Objects.requireNonNull(settings, "no settings given");
        Objects.requireNonNull(parameters, "no parameters given");
    }

    /**
     * @param controller a bundled controller or a class on the classpath
     * @param settings the robot's settings; no parameters
     */
    public RobotSetup(String controller, Settings settings) {
        this(controller, settings, Parameters.NONE);
    }
}
