package org.kheperasim.sim.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.RobotKind;

/** The {@code --robot-file} option's wiring, shared by the commands that take {@code --arena}. */
final class RobotFiles {

    private RobotFiles() {
    }

    /**
     * @param arena the {@code --arena} value
     * @param robotFile the {@code --robot-file} value, or null
     * @return the arena, its robots without a type of the robot file's type
     */
    static Arena arena(String arena, String robotFile) {
        Arena a = ArenaFormat.resolve(arena);
        return robotFile == null ? a : a.withDefaultRobot(RobotKind.of(robotFile));
    }

    /** @return the robot files a run of this arena reads (for a sandbox to show), absolute */
    static List<Path> files(String arena, String robotFile) {
        List<Path> out = new ArrayList<>();
        Path arenaFile = Files.isRegularFile(Path.of(arena)) ? Path.of(arena) : null;
        for (RobotKind k : ArenaFormat.resolve(arena).robotKinds()) {
            Path f = k.file(arenaFile);
            if (f != null && !out.contains(f)) {
                out.add(f);
            }
        }
        if (robotFile != null && Files.isRegularFile(Path.of(robotFile))) {
            out.add(Path.of(robotFile).toAbsolutePath());
        }
        return out;
    }
}
