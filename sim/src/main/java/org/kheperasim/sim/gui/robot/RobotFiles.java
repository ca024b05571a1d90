package org.kheperasim.sim.gui.robot;

import java.nio.file.Path;
import java.util.List;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The robot editor's robot files. Until the robot file's reader and writer are merged (branch
 * {@code robots}), it offers the Khepera I and refuses to read or write a file.
 */
public final class RobotFiles implements RobotFileStore {
    private static final String NOT_YET = "robot files cannot be read or written in this build yet (the reader and"
            + " writer come with the robots branch); edit a bundled robot and use Try in arena";

    /** @return the bundled robots, the default first */
    public static List<RobotType> bundled() {
        return List.of(RobotTypes.KHEPERA1);
    }

    @Override
    public RobotType load(Path file) {
        throw new IllegalStateException(NOT_YET);
    }

    @Override
    public void save(RobotType type, Path file) {
        throw new IllegalStateException(NOT_YET);
    }

    @Override
    public String problem(RobotType type) {
        return null;
    }
}
