package org.kheperasim.sim.arena;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import java.util.regex.Pattern;

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

    private static final String FORMAT_NAME = "khepera-arena";
    private static final String VERSION = "1";
    private static final List<String> BUNDLED = List.of("lab", "maze");
    private static final String KEYWORDS = "name, size, robot, wall, light, cap, region";
    private static final String LIGHT_KEYWORDS = "range, intensity, radius, direction, spread";
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern NOT_FINITE =
            Pattern.compile("[+-]?(nan|inf|infinity)", Pattern.CASE_INSENSITIVE);
    private static final Pattern LINE_BREAK = Pattern.compile("\r\n|\r|\n");
    private static final Pattern BLANKS = Pattern.compile("\\s+");

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
        return new Parser(text, sourceName).parse();
    }

    /**
     * Reads an arena file (UTF-8).
     *
     * @param file the file
     * @return the arena
     * @throws ArenaFormatException if the content is not a valid arena (named by the path as given)
     * @throws UncheckedIOException if the file cannot be read
     */
    public static Arena load(Path file) {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read arena file " + file + ": " + e, e);
        }
        return parse(text, file.toString());
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
        throw new IllegalArgumentException("no arena file '" + nameOrPath
                + "' and no bundled arena of that name; give the path to a " + EXTENSION
                + " file or one of the bundled arenas: " + String.join(", ", BUNDLED));
    }

    /**
     * Writes an arena as canonical text: header, name, size, robots, walls, lights, caps, regions,
     * one item per line, no comments; every number in its shortest exact decimal form; optional
     * keywords only where they differ from the defaults. {@code parse(write(a), s).equals(a)} for
     * every arena that {@link #parse} accepts.
     *
     * @param arena the arena
     * @return the text, lines ending in {@code \n}
     */
    public static String write(Arena arena) {
        StringBuilder sb = new StringBuilder(256);
        sb.append(HEADER).append('\n');
        sb.append("name ").append(arena.name()).append('\n');
        line(sb, "size", arena.width(), arena.height());
        for (Pose p : arena.robots()) {
            line(sb, "robot", p.x(), p.y(), p.headingDeg());
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
     * Saves an arena atomically: the canonical text goes to a temporary file in the same directory,
     * which then replaces {@code file} in one rename, so a reader never sees half a file and a
     * failed save leaves the old file intact.
     *
     * @param arena the arena
     * @param file  where to save it
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void save(Arena arena, Path file) {
        Path target = file.toAbsolutePath();
        Path dir = target.getParent();
        byte[] bytes = write(arena).getBytes(StandardCharsets.UTF_8);
        Path tmp = null;
        try {
            tmp = Files.createTempFile(dir, "." + target.getFileName() + ".", ".tmp");
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
                ByteBuffer buf = ByteBuffer.wrap(bytes);
                while (buf.hasRemaining()) {
                    ch.write(buf);
                }
                ch.force(true);
            }
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            tmp = null;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save arena file " + file + ": " + e, e);
        } finally {
            if (tmp != null) {
                try {
                    Files.deleteIfExists(tmp);
                } catch (IOException e) {
                    // The save already failed; that error is the one to report.
                }
            }
        }
    }

    /**
     * Identifies an arena's content, e.g. in a trace header: equal arenas have equal hashes
     * whatever the comments and layout of their files.
     *
     * @param arena the arena
     * @return lower-case hex SHA-256 of {@link #write}'s UTF-8 text
     */
    public static String sha256(Arena arena) {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            return HexFormat.of().formatHex(md.digest(write(arena).getBytes(StandardCharsets.UTF_8)));
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

    /** One parse of one text; collects items with their line numbers, then checks the whole. */
    private static final class Parser {
        private final String source;
        private final String[] lines;
        private int lineNo;
        private int headerLine;
        private String name;
        private int nameLine;
        private double width;
        private double height;
        private int sizeLine;
        private final List<Pose> robots = new ArrayList<>();
        private final List<Integer> robotLines = new ArrayList<>();
        private final List<Wall> walls = new ArrayList<>();
        private final List<Integer> wallLines = new ArrayList<>();
        private final List<Light> lights = new ArrayList<>();
        private final List<Integer> lightLines = new ArrayList<>();
        private final List<Cap> caps = new ArrayList<>();
        private final List<Integer> capLines = new ArrayList<>();
        private final List<Region> regions = new ArrayList<>();
        private final List<Integer> regionLines = new ArrayList<>();
        private final Map<String, Integer> regionNames = new HashMap<>();

        Parser(String text, String source) {
            this.source = source;
            String t = text.startsWith("\uFEFF") ? text.substring(1) : text;
            this.lines = LINE_BREAK.split(t, -1);
        }

        Arena parse() {
            for (int i = 0; i < lines.length; i++) {
                String content = lines[i];
                int hash = content.indexOf('#');
                if (hash >= 0) {
                    content = content.substring(0, hash);
                }
                content = content.strip();
                if (content.isEmpty()) {
                    continue;
                }
                lineNo = i + 1;
                String[] tokens = BLANKS.split(content);
                if (headerLine == 0) {
                    header(tokens);
                } else {
                    item(tokens);
                }
            }
            if (headerLine == 0) {
                throw error(1, "expected '" + HEADER + "', found no content; start the file with the line '"
                        + HEADER + "'");
            }
            if (sizeLine == 0) {
                throw error(headerLine, "no 'size' line; add 'size <width> <height>' in mm after the header,"
                        + " e.g. 'size 1219.2 1219.2'");
            }
            if (robots.isEmpty()) {
                throw error(headerLine, "no 'robot' line; add at least one start pose"
                        + " 'robot <x> <y> <heading>', e.g. 'robot 609.6 609.6 90'");
            }
            checkInside();
            int maxCaps = Short.MAX_VALUE - OccupancyGrid.FIRST_CAP + 1;
            if (caps.size() > maxCaps) {
                throw error(capLines.get(maxCaps), "too many caps: the grid numbers at most " + maxCaps
                        + "; remove caps from here on");
            }
            Arena arena = build(headerLine, () -> new Arena(name != null ? name : nameFromSource(),
                    width, height, robots, walls, lights, caps, regions));
            checkRobotsClear(arena);
            return arena;
        }

        private void header(String[] tokens) {
            headerLine = lineNo;
            if (tokens.length == 2 && tokens[0].equals(FORMAT_NAME) && tokens[1].equals(VERSION)) {
                return;
            }
            if (tokens[0].equals(FORMAT_NAME) && tokens.length == 2) {
                throw error(lineNo, "expected '" + HEADER + "', found version '" + tokens[1]
                        + "', which this simulator cannot read; write the file in version " + VERSION);
            }
            throw error(lineNo, "expected '" + HEADER + "' as the first line, found '"
                    + String.join(" ", tokens) + "'; start the file with the line '" + HEADER + "'");
        }

        private void item(String[] t) {
            switch (t[0]) {
                case "name" -> name(t);
                case "size" -> size(t);
                case "robot" -> {
                    double[] n = numbers(t, 1, "robot needs x y heading (3 numbers: mm, mm, degrees)",
                            "x", "y", "heading");
                    robots.add(build(lineNo, () -> new Pose(n[0], n[1], n[2])));
                    robotLines.add(lineNo);
                }
                case "wall" -> {
                    double[] n = numbers(t, 1, "wall needs x1 y1 x2 y2 thickness (5 numbers, mm)",
                            "x1", "y1", "x2", "y2", "thickness");
                    walls.add(build(lineNo, () -> new Wall(n[0], n[1], n[2], n[3], n[4])));
                    wallLines.add(lineNo);
                }
                case "light" -> light(t);
                case "cap" -> cap(t);
                case "region" -> region(t);
                default -> throw error(lineNo, "unknown keyword '" + t[0] + "'; valid keywords are " + KEYWORDS);
            }
        }

        private void name(String[] t) {
            if (nameLine != 0) {
                throw error(lineNo, "a second 'name' line (the first is on line " + nameLine + "); keep one");
            }
            if (t.length != 2 || !Region.NAME.matcher(t[1]).matches()) {
                throw error(lineNo, "name needs one word of letters, digits, '_' and '-', e.g. 'name maze'");
            }
            name = t[1];
            nameLine = lineNo;
        }

        private void size(String[] t) {
            if (sizeLine != 0) {
                throw error(lineNo, "a second 'size' line (the first is on line " + sizeLine + "); keep one");
            }
            double[] n = numbers(t, 1, "size needs width height (2 numbers, mm)", "width", "height");
            build(lineNo, () -> Numbers.positive("arena width", n[0], "mm"));
            build(lineNo, () -> Numbers.positive("arena height", n[1], "mm"));
            width = n[0];
            height = n[1];
            sizeLine = lineNo;
        }

        private void light(String[] t) {
            if (t.length < 3) {
                throw error(lineNo, "light needs x y, then optional keyword-value pairs ("
                        + LIGHT_KEYWORDS + "), got " + (t.length - 1) + " values");
            }
            double x = number(t[1], "light x");
            double y = number(t[2], "light y");
            double[] opt = {Light.DEFAULT_RANGE, Light.DEFAULT_INTENSITY, Light.DEFAULT_RADIUS,
                    Light.DEFAULT_DIRECTION, Light.DEFAULT_SPREAD};
            boolean[] given = new boolean[opt.length];
            for (int i = 3; i < t.length; i += 2) {
                int k = switch (t[i]) {
                    case "range" -> 0;
                    case "intensity" -> 1;
                    case "radius" -> 2;
                    case "direction" -> 3;
                    case "spread" -> 4;
                    default -> -1;
                };
                if (k < 0) {
                    if (NUMBER.matcher(t[i]).matches()) {
                        throw error(lineNo, "light has a number '" + t[i] + "' where a keyword belongs;"
                                + " after x y write keyword-value pairs such as 'range 400' ("
                                + LIGHT_KEYWORDS + ")");
                    }
                    throw error(lineNo, "unknown light keyword '" + t[i] + "'; valid light keywords are "
                            + LIGHT_KEYWORDS);
                }
                if (given[k]) {
                    throw error(lineNo, "light keyword '" + t[i] + "' appears twice; keep one");
                }
                if (i + 1 >= t.length) {
                    throw error(lineNo, "light keyword '" + t[i] + "' needs a value after it");
                }
                given[k] = true;
                opt[k] = number(t[i + 1], "light " + t[i]);
            }
            lights.add(build(lineNo, () -> new Light(x, y, opt[2], opt[0], opt[1], opt[3], opt[4])));
            lightLines.add(lineNo);
        }

        private void cap(String[] t) {
            String usage = "cap needs x y, optionally followed by 'radius <mm>'";
            if (t.length == 5 && !t[3].equals("radius") && !NUMBER.matcher(t[3]).matches()) {
                throw error(lineNo, "unknown cap keyword '" + t[3] + "'; the only cap keyword is radius");
            }
            if (t.length != 3 && !(t.length == 5 && t[3].equals("radius"))) {
                throw error(lineNo, usage + ", got " + (t.length - 1) + " values");
            }
            double x = number(t[1], "cap x");
            double y = number(t[2], "cap y");
            double r = t.length == 5 ? number(t[4], "cap radius") : Cap.DEFAULT_RADIUS;
            caps.add(build(lineNo, () -> new Cap(x, y, r)));
            capLines.add(lineNo);
        }

        private void region(String[] t) {
            String usage = "region needs name x1 y1 x2 y2 (a name and 4 numbers, mm)";
            if (t.length != 6) {
                throw error(lineNo, usage + ", got " + (t.length - 1) + " values");
            }
            double[] n = numbers(t, 2, usage, "x1", "y1", "x2", "y2");
            Region r = build(lineNo, () -> new Region(t[1], n[0], n[1], n[2], n[3]));
            Integer first = regionNames.putIfAbsent(r.name(), lineNo);
            if (first != null) {
                throw error(lineNo, "region name '" + r.name() + "' is already used on line " + first
                        + "; give each region its own name");
            }
            regions.add(r);
            regionLines.add(lineNo);
        }

        /** Parses {@code t[from..]} as exactly {@code fields.length} numbers. */
        private double[] numbers(String[] t, int from, String usage, String... fields) {
            int count = t.length - from;
            if (count != fields.length) {
                throw error(lineNo, usage + ", got " + count + (count == 1 ? " value" : " values"));
            }
            double[] n = new double[count];
            for (int i = 0; i < count; i++) {
                n[i] = number(t[from + i], t[0] + " " + fields[i]);
            }
            return n;
        }

        private double number(String token, String what) {
            if (NUMBER.matcher(token).matches()) {
                double d = Double.parseDouble(token);
                if (Double.isFinite(d)) {
                    return d;
                }
                throw error(lineNo, what + " is '" + token + "', too large to be a number of mm; give a finite number");
            }
            if (NOT_FINITE.matcher(token).matches()) {
                throw error(lineNo, what + " is '" + token + "'; give a finite number such as 12.5");
            }
            throw error(lineNo, what + " is '" + token + "', not a number; write a decimal number such as 12.5");
        }

        private void checkInside() {
            for (int i = 0; i < robots.size(); i++) {
                Pose p = robots.get(i);
                inside("robot", p.x(), p.y(), robotLines.get(i));
            }
            for (int i = 0; i < walls.size(); i++) {
                Wall w = walls.get(i);
                inside("wall end", w.x1(), w.y1(), wallLines.get(i));
                inside("wall end", w.x2(), w.y2(), wallLines.get(i));
            }
            for (int i = 0; i < lights.size(); i++) {
                inside("light", lights.get(i).x(), lights.get(i).y(), lightLines.get(i));
            }
            for (int i = 0; i < caps.size(); i++) {
                inside("cap", caps.get(i).x(), caps.get(i).y(), capLines.get(i));
            }
            for (int i = 0; i < regions.size(); i++) {
                Region r = regions.get(i);
                inside("region corner", r.x1(), r.y1(), regionLines.get(i));
                inside("region corner", r.x2(), r.y2(), regionLines.get(i));
            }
        }

        private void inside(String what, double x, double y, int line) {
            if (x < 0 || y < 0 || x > width || y > height) {
                String w = Numbers.format(width);
                String h = Numbers.format(height);
                throw error(line, what + " at " + point(x, y) + " lies outside the " + w + " x " + h
                        + " mm arena; keep x within 0.." + w + " and y within 0.." + h);
            }
        }

        /**
         * Refuses a robot whose body overlaps a wall or lamp cell, the edge of the grid (which is
         * wall), or another robot. Caps may touch a robot: it pushes them.
         */
        private void checkRobotsClear(Arena arena) {
            OccupancyGrid grid = OccupancyGrid.of(arena);
            double radius = Arena.ROBOT_RADIUS_MM;
            double cell = grid.cellSize();
            for (int i = 0; i < robots.size(); i++) {
                Pose p = robots.get(i);
                double best = radius;
                int bestCol = 0;
                int bestRow = 0;
                for (int r = grid.row(p.y() - radius); r <= grid.row(p.y() + radius); r++) {
                    for (int c = grid.col(p.x() - radius); c <= grid.col(p.x() + radius); c++) {
                        int id = grid.id(c, r);
                        if (id != OccupancyGrid.WALL && id != OccupancyGrid.LIGHT) {
                            continue;
                        }
                        double dx = Math.max(0, Math.max(c * cell - p.x(), p.x() - (c + 1) * cell));
                        double dy = Math.max(0, Math.max(r * cell - p.y(), p.y() - (r + 1) * cell));
                        double d = Math.sqrt(dx * dx + dy * dy);
                        if (d < best) {
                            best = d;
                            bestCol = c;
                            bestRow = r;
                        }
                    }
                }
                if (best < radius) {
                    boolean off = bestCol < 0 || bestRow < 0 || bestCol >= grid.cols() || bestRow >= grid.rows();
                    String what = off ? "the edge of the arena"
                            : (grid.id(bestCol, bestRow) == OccupancyGrid.LIGHT ? "a light" : "a wall")
                            + String.format(Locale.ROOT, " near (%.1f, %.1f)",
                                    grid.cellCentreX(bestCol), grid.cellCentreY(bestRow));
                    throw error(robotLines.get(i), "robot at " + point(p.x(), p.y()) + " overlaps " + what
                            + "; its body is a " + Numbers.format(radius) + " mm radius disc,"
                            + " so move its centre that far from walls, lights and the edge");
                }
                for (int j = 0; j < i; j++) {
                    Pose q = robots.get(j);
                    double d = Math.hypot(p.x() - q.x(), p.y() - q.y());
                    if (d < 2 * radius) {
                        throw error(robotLines.get(i), "robot at " + point(p.x(), p.y())
                                + " overlaps the robot on line " + robotLines.get(j) + ": their centres are "
                                + String.format(Locale.ROOT, "%.1f", d) + " mm apart, less than "
                                + Numbers.format(2 * radius) + " mm; move one of them");
                    }
                }
            }
        }

        private String nameFromSource() {
            String base = source.substring(Math.max(source.lastIndexOf('/'), source.lastIndexOf('\\')) + 1);
            if (base.endsWith(EXTENSION)) {
                base = base.substring(0, base.length() - EXTENSION.length());
            }
            base = base.replaceAll("[^A-Za-z0-9_-]", "_");
            return base.isEmpty() ? "arena" : base;
        }

        private <T> T build(int line, Supplier<T> constructor) {
            try {
                return constructor.get();
            } catch (IllegalArgumentException e) {
                throw error(line, e.getMessage());
            }
        }

        private ArenaFormatException error(int line, String what) {
            return new ArenaFormatException(source, line, what);
        }

        private static String point(double x, double y) {
            return "(" + Numbers.format(x) + ", " + Numbers.format(y) + ")";
        }
    }
}
