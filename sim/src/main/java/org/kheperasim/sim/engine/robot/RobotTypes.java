package org.kheperasim.sim.engine.robot;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.files.TextFiles;

/**
 * The bundled robot types, read from the robot files in this package's resources, and robot
 * files on disk. {@link #KHEPERA1}, the paper's robot, is the default.
 */
public final class RobotTypes {
    /** The bundled robots' names, the default first. */
    public static final List<String> BUNDLED = List.of("khepera1", "khepera2", "epuck", "wsu");
    /** The largest robot file read, bytes. */
    private static final long MAX_BYTES = 1 << 20;

    /** The Khepera I of the paper (khepera1.yaml). */
    public static final RobotType KHEPERA1 = bundled("khepera1");

    private static final RobotType KHEPERA2 = bundled("khepera2");
    private static final RobotType EPUCK = bundled("epuck");
    /** The original WSU simulator's robot (wsu.yaml), the robot of the {@code wsu} profile. */
    public static final RobotType WSU = bundled("wsu");

    private RobotTypes() {
    }

    /** @return the bundled robot types, the default first */
    public static List<RobotType> all() {
        return List.of(KHEPERA1, KHEPERA2, EPUCK, WSU);
    }

    /**
     * @param name a bundled robot's name
     * @return that robot
     * @throws IllegalArgumentException naming the bundled robots when there is none of that name
     */
    public static RobotType named(String name) {
        for (RobotType t : all()) {
            if (t.name().equals(name)) {
                return t;
            }
        }
        throw new IllegalArgumentException("robot '" + name + "' is not bundled; use one of "
                + String.join(", ", BUNDLED)
                + ", or a robot file's path");
    }

    /**
     * A robot by what a user wrote: a bundled robot's name, or else the path of a robot file.
     *
     * @param spec {@code epuck}, or {@code robots/tri.yaml}
     * @param base the folder a relative path is taken from (the arena file's), or null: the working folder
     * @return the robot
     * @throws InputFileException naming the file and line when a robot file is wrong or missing
     */
    public static RobotType resolve(String spec, Path base) {
        if (BUNDLED.contains(spec)) {
            return named(spec);
        }
        Path p = Path.of(spec);
        if (!p.isAbsolute() && base != null) {
            p = base.resolve(p);
        }
        return load(p);
    }

    /**
     * @param file a robot file, or a calibration file ({@link Calibration})
     * @return the robot it describes
     * @throws InputFileException naming the file (and line) when it cannot be read or is wrong
     */
    public static RobotType load(Path file) {
        String source = file.toString();
        if (!java.nio.file.Files.isRegularFile(file)) {
            throw new RobotFileException(source, 0,
                    "no such robot file; give a bundled robot (" + String.join(", ", BUNDLED)
                    + ") or the path of a robot file");
        }
        String text = TextFiles.readUtf8(file, MAX_BYTES, "robot file",
                (line, what) -> new RobotFileException(source, line, what));
        // A calibration (khepera-link calibrate) is the robot it measured.
        return Calibration.is(text) ? Calibration.parse(source, file, text).type()
                : RobotFileReader.parse(source, text, file.toAbsolutePath().getParent());
    }

    /**
     * @param name {@code khepera1}, {@code khepera2}, or {@code sample:PATH} (a table fitted to a
     *     sampled wall file, {@link SampleResponses})
     * @return that robot's proximity response, for the {@code prox.profile} setting
     */
    public static Response profile(String name) {
        if (name.startsWith(SampleResponses.PREFIX)) {
            return SampleResponses.fit(name.substring(SampleResponses.PREFIX.length()), KHEPERA1).table();
        }
        return switch (name) {
            case "khepera1" -> KHEPERA1.proximity().response();
            case "khepera2" -> KHEPERA2.proximity().response();
            default -> throw new IllegalArgumentException("unknown proximity profile '" + name
                    + "'; use one of [khepera1, khepera2] or sample:PATH");
        };
    }

    /** @param name a bundled robot @return its robot file's text, as bundled (comments and all) */
    public static String bundledText(String name) {
        String resource = name + ".yaml";
        try (InputStream in = RobotTypes.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("the bundled robot file " + resource + " is missing from the build");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the bundled robot file " + resource, e);
        }
    }

    private static RobotType bundled(String name) {
        return RobotFileReader.parse(name + ".yaml (bundled)", bundledText(name));
    }
}
