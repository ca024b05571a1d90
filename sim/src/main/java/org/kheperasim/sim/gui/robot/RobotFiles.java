package org.kheperasim.sim.gui.robot;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import org.kheperasim.sim.engine.robot.RobotFileReader;
import org.kheperasim.sim.engine.robot.RobotFileWriter;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * The robot editor's robot files: read by {@link RobotTypes#load}, written by
 * {@link RobotFileWriter} (atomically), and an edited robot checked by writing it and reading it
 * back with {@link RobotFileReader}, so that the editor refuses what a saved file could not hold.
 */
public final class RobotFiles implements RobotFileStore {
    /** The name a check's text goes by, cut from the reader's message. */
    private static final String CHECKED = "edited robot";

    /** @return the bundled robots, the default first */
    public static List<RobotType> bundled() {
        return RobotTypes.all();
    }

    @Override
    public RobotType load(Path file) {
        return RobotTypes.load(file);
    }

    @Override
    public void save(RobotType type, Path file) {
        try {
            AtomicFiles.write(file, RobotFileWriter.write(type));
        } catch (IOException e) {
            throw new UncheckedIOException(e.getMessage(), e);
        }
    }

    @Override
    public String problem(RobotType type) {
        try {
            RobotFileReader.parse(CHECKED, RobotFileWriter.write(type));
            return null;
        } catch (RuntimeException e) {
            String m = String.valueOf(e.getMessage());
            return m.replaceFirst("^" + CHECKED + ":\\d+: ", "");
        }
    }
}
