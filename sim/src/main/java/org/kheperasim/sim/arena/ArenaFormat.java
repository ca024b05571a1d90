package org.kheperasim.sim.arena;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.TextFiles;

/**
 * Reads and writes arena files: line-oriented text a person writes by hand, with comments. The
 * format is described in {@code docs/arena-format.md}; in short:
 * <pre>
 * khepera-arena 1
 * name maze
 * size 1219.2 1219.2
 * robot 150 150 90
 * wall 0 4 1219.2 4 8
 * light 600 600 range 400 intensity 1 radius 6 direction 90 spread 60
 * cap 500 500 radius 9
 * region start 0 0 243.84 243.84
 * </pre>
 * A bad file is refused with an {@link ArenaFormatException} whose message reads
 * {@code source:line: what is wrong and the fix}.
 */
public final class ArenaFormat {

    /** The first line of every arena file: format name and version. */
    public static final String HEADER = "khepera-arena 1";
    /** File name extension of arena files, with the dot. */
    public static final String EXTENSION = ".arena";

    /** The arenas in {@code arenas/} at the top of the repository, which travel inside the jar. */
    private static final List<String> BUNDLED =
            List.of("lab", "maze-easy", "maze", "maze-hard", "beacon-maze", "two-rooms");

    private ArenaFormat() {
    }

    /** @return the names of the arenas bundled with the simulator, for {@link #loadBundled} */
    public static List<String> bundledNames() {
        return BUNDLED;
    }

    /**
     * Parses arena text and checks it: every number finite, sizes positive, everything inside the
     * arena, region names unique, no robot starting inside a wall, a lamp, the edge or another
     * robot.
     *
     * @param text       the file's content
     * @param sourceName how error messages name the file, e.g. its path; an arena without a
     *                   {@code name} line is named after it
     * @return the arena
     * @throws ArenaFormatException naming the source and the line at fault
     */
    public static Arena parse(String text, String sourceName) {
        return new ArenaParser(text, sourceName, null).parse();
    }

    /**
     * Reads an arena file (UTF-8).
     *
     * @param file the file
     * @return the arena
     * @throws ArenaFormatException if the content is not a valid arena (named by the path as given),
     *                              is not UTF-8 or is larger than {@link ArenaLimits#MAX_FILE_BYTES}
     * @throws UncheckedIOException if the file cannot be read
     */
    public static Arena load(Path file) {
        String source = file.toString();
        String text = TextFiles.readUtf8(file, ArenaLimits.MAX_FILE_BYTES, "arena file",
                (line, what) -> new ArenaFormatException(source, line, what));
        return new ArenaParser(text, source, file.toAbsolutePath().getParent()).parse();
    }

    /**
     * Reads an arena that ships inside the simulator (classpath resource
     * {@code arenas/<name>.arena}).
     *
     * @param name a bundled arena's name, e.g. {@code maze}
     * @return the arena
     * @throws IllegalArgumentException if there is no bundled arena of that name
     */
    public static Arena loadBundled(String name) {
        String text = bundledText(name);
        if (text == null) {
            throw new IllegalArgumentException("no bundled arena '" + name + "'; the bundled arenas are "
                    + String.join(", ", BUNDLED));
        }
        return parse(text, name + EXTENSION);
    }

    /**
     * Finds an arena the way a user names one on the command line: an existing file path first,
     * else a bundled arena's name.
     *
     * @param nameOrPath a path to a {@code .arena} file (or a WSU world file, see {@link ArenaFiles}),
     *                   or a bundled name such as {@code lab}
     * @return the arena
     * @throws IllegalArgumentException if it is neither an existing file nor a bundled name
     * @throws ArenaFormatException     if the file is not a valid arena
     * @throws org.kheperasim.sim.arena.wsu.WsuWorldException if a WSU world file is damaged
     */
    public static Arena resolve(String nameOrPath) {
        Path path = null;
        try {
            path = Path.of(nameOrPath);
        } catch (InvalidPathException e) {
            // Not a usable path: it can still be a bundled name.
        }
        if (path != null && Files.isRegularFile(path)) {
            return ArenaFiles.load(path); // a text arena, or a WSU world file recognised by its content
        }
        String text = bundledText(nameOrPath);
        if (text != null) {
            return parse(text, nameOrPath + EXTENSION);
        }
        if (path != null && Files.exists(path)) {
            return load(path);   // a folder, a pipe, a device: refused, saying what it is, without opening it
        }
        throw new IllegalArgumentException("no arena file '" + nameOrPath
                + "' and no bundled arena of that name; give the path to a " + EXTENSION
                + " file or one of the bundled arenas: " + String.join(", ", BUNDLED));
    }

    /**
     * Writes an arena as canonical text: header, name, size, robots, walls, lights, caps, regions,
     * then the assignment ({@code time-limit}, then the {@code task} lines in order), one item per
     * line, no comments; every number in its shortest exact decimal form; optional keywords only where they differ from
     * the defaults. {@code parse(write(a), s).equals(a)} for every arena that {@link #parse} accepts.
     *
     * @param arena the arena
     * @return the text, lines ending in {@code \n}
     */
    public static String write(Arena arena) {
        StringBuilder sb = new StringBuilder(writeWorld(arena));
        Assignment a = arena.assignment();
        if (a.timeLimitSeconds() > 0) {
            line(sb, "time-limit", a.timeLimitSeconds());
        }
        for (Task t : a.tasks()) {
            sb.append(t.line()).append('\n');
        }
        return sb.toString();
    }

    /** The canonical lines of what the simulation sees: everything but the assignment. */
    private static String writeWorld(Arena arena) {
        StringBuilder sb = new StringBuilder(256);
        sb.append(HEADER).append('\n');
        sb.append("name ").append(arena.name()).append('\n');
        line(sb, "size", arena.width(), arena.height());
        for (int i = 0; i < arena.robots().size(); i++) {
            Pose p = arena.robots().get(i);
            RobotKind k = arena.robotKinds().get(i);
            if (k.isDefault()) {
                line(sb, "robot", p.x(), p.y(), p.headingDeg());
            } else {
                sb.append("robot ").append(Numbers.format(p.x())).append(' ').append(Numbers.format(p.y())).append(' ')
                        .append(Numbers.format(p.headingDeg())).append(' ').append(k.spec()).append('\n');
            }
        }
        for (Wall w : arena.walls()) {
            line(sb, "wall", w.x1(), w.y1(), w.x2(), w.y2(), w.thickness());
        }
        for (Light l : arena.lights()) {
            sb.append("light ").append(Numbers.format(l.x())).append(' ').append(Numbers.format(l.y()));
            option(sb, "range", l.range(), Light.DEFAULT_RANGE);
            option(sb, "intensity", l.intensity(), Light.DEFAULT_INTENSITY);
            option(sb, "radius", l.radius(), Light.DEFAULT_RADIUS);
            option(sb, "direction", l.directionDeg(), Light.DEFAULT_DIRECTION);
            option(sb, "spread", l.spreadDeg(), Light.DEFAULT_SPREAD);
            sb.append('\n');
        }
        for (Cap c : arena.caps()) {
            sb.append("cap ").append(Numbers.format(c.x())).append(' ').append(Numbers.format(c.y()));
            option(sb, "radius", c.radius(), Cap.DEFAULT_RADIUS);
            sb.append('\n');
        }
        for (Region r : arena.regions()) {
            sb.append("region ").append(r.name());
            line(sb, "", r.x1(), r.y1(), r.x2(), r.y2());
        }
        return sb.toString();
    }

    /**
     * Saves an arena atomically ({@link AtomicFiles}): the canonical text goes to a temporary file
     * in the same directory, which then replaces {@code file} in one rename, so a reader never sees
     * half a file and a failed save leaves the old file intact; a symbolic link stays a link, and
     * the file keeps its permissions.
     *
     * @param arena the arena
     * @param file  where to save it
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void save(Arena arena, Path file) {
        try {
            AtomicFiles.write(file, write(arena));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save arena file " + file + ": " + e, e);
        }
    }

    /**
     * Identifies an arena's content, e.g. in a trace header: equal arenas have equal hashes
     * whatever the comments and layout of their files.
     *
     * @param arena the arena
     * @return lower-case hex SHA-256 of {@link #write}'s UTF-8 text less the assignment's lines
     *     ({@code time-limit}, {@code task}): they only score a run, so adding a task to an arena
     *     changes no trace and a recorded run still verifies
     */
    public static String sha256(Arena arena) {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            return HexFormat.of().formatHex(md.digest(writeWorld(arena).getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this Java runtime lacks SHA-256, which every JDK must have", e);
        }
    }

    private static String bundledText(String name) {
        if (!Region.NAME.matcher(name).matches()) {
            return null;
        }
        try (InputStream in = ArenaFormat.class.getClassLoader()
                .getResourceAsStream("arenas/" + name + EXTENSION)) {
            return in == null ? null : new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read bundled arena " + name + ": " + e, e);
        }
    }

    private static void line(StringBuilder sb, String keyword, double... numbers) {
        sb.append(keyword);
        for (double d : numbers) {
            sb.append(' ').append(Numbers.format(d));
        }
        sb.append('\n');
    }

    private static void option(StringBuilder sb, String keyword, double value, double dflt) {
        if (Double.compare(value, dflt) != 0) {
            sb.append(' ').append(keyword).append(' ').append(Numbers.format(value));
        }
    }
}
