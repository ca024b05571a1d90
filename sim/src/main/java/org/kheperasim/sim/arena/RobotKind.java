package org.kheperasim.sim.arena;

import java.util.Objects;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * Which robot an arena's {@code robot} line places: what the line wrote (a bundled robot's name or
 * a robot file's path, as written) and the type it names.
 *
 * @param spec the line's last word ({@code epuck}, {@code robots/tri.yaml}); {@code khepera1} when it has none
 * @param type the robot type
 */
public record RobotKind(String spec, RobotType type) {
    /** A robot line without a type: the paper's Khepera I. */
    public static final RobotKind DEFAULT = new RobotKind("khepera1", RobotTypes.KHEPERA1);

    public RobotKind {
        Objects.requireNonNull(spec, "spec");
        Objects.requireNonNull(type, "type");
    }

    /**
     * @param spec what a user wrote: a bundled robot's name or a robot file's path (from the working folder)
     * @return the kind it names
     * @throws org.kheperasim.sim.files.InputFileException naming the robot file and line when it is wrong
     */
    public static RobotKind of(String spec) {
        return new RobotKind(spec, RobotTypes.resolve(spec, null));
    }

    /**
     * @param arenaFile the arena file the kind's line is in, or null
     * @return the robot file this kind names (absolute), or null for a bundled robot
     */
    public java.nio.file.Path file(java.nio.file.Path arenaFile) {
        if (RobotTypes.BUNDLED.contains(spec)) {
            return null;
        }
        java.nio.file.Path p = java.nio.file.Path.of(spec);
        java.nio.file.Path base = arenaFile == null ? null : arenaFile.toAbsolutePath().getParent();
        return (p.isAbsolute() || base == null ? p : base.resolve(p)).toAbsolutePath();
    }

    /** @return true when the line needs no type word (the default robot) */
    public boolean isDefault() {
        return spec.equals(DEFAULT.spec) && type.equals(DEFAULT.type);
    }
}
