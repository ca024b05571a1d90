package org.kheperasim.sim.gui.robot;

import java.nio.file.Path;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * Where the robot editor reads and writes robot files ({@code docs/robot-files.md}). The editor
 * knows nothing of the format; {@link RobotFiles} is the one that does.
 */
public interface RobotFileStore {
    /**
     * @param file a robot file
     * @return the robot type it describes
     * @throws RuntimeException with a one-line message naming the file, the line and the fix
     */
    RobotType load(Path file);

    /**
     * @param type the robot type to write
     * @param file where (replaced whole, or not at all)
     * @throws RuntimeException with a one-line message when it cannot be written
     */
    void save(RobotType type, Path file);

    /**
     * @param type a robot type the editor made
     * @return what the robot file's reader would refuse in it, one line, or null when a saved file reads back
     */
    String problem(RobotType type);
}
