package org.kheperasim.sim.arena;

import static org.kheperasim.sim.arena.ArenaLimits.MAX_ANGLE_DEG;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import java.util.regex.Pattern;

/**
 * One parse of one arena text ({@link ArenaFormat#parse}): collects items with their line numbers,
 * checks each line's numbers against {@link ArenaLimits} as it goes, then checks the whole. Every
 * failure is an {@link ArenaFormatException} naming the line.
 */
final class ArenaParser {

    private static final String FORMAT_NAME = "khepera-arena";
    private static final String VERSION = "1";
    private static final String KEYWORDS = "name, size, wsu-world, robot, wall, light, cap, region, task, time-limit";
    private static final String LIGHT_KEYWORDS = "range, intensity, radius, direction, spread";
    private static final Pattern LINE_BREAK = Pattern.compile("\r\n|\r|\n");
    private static final Pattern BLANKS = Pattern.compile("\\s+");

    private final String source;
    private final Path folder;
    private final TokenNumbers tokens;
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
    private final List<RobotKind> robotKinds = new ArrayList<>();
    private final List<Wall> walls = new ArrayList<>();
    private final List<Integer> wallLines = new ArrayList<>();
    private final List<Light> lights = new ArrayList<>();
    private final List<Integer> lightLines = new ArrayList<>();
    private final List<Cap> caps = new ArrayList<>();
    private final List<Integer> capLines = new ArrayList<>();
    private final List<Region> regions = new ArrayList<>();
    private final List<Integer> regionLines = new ArrayList<>();
    private final Map<String, Integer> regionNames = new HashMap<>();
    private final List<Task> tasks = new ArrayList<>();
    private final List<Integer> taskLines = new ArrayList<>();
    private double timeLimit;
    private int timeLimitLine;
    private int worldLine;
    private Pose worldRobot;

    /**
     * @param folder the arena file's folder, for a {@code wsu-world} path; null for a text that is not a file
     */
    ArenaParser(String text, String source, Path folder) {
        this.source = source;
        this.folder = folder;
        this.tokens = new TokenNumbers(source);
        String t = text.startsWith("\uFEFF") ? text.substring(1) : text;
        this.lines = LINE_BREAK.split(t, -1);
    }

    Arena parse() {
        try {
            return parseChecked();
        } catch (ArenaFormatException e) {
            throw e;
        } catch (RuntimeException e) {
            // A reader's promise: whatever the text, the error names the file and the line.
            throw error(Math.max(lineNo, 1), "cannot read this line (" + e + "); this is a bug in the"
                    + " simulator, please report it with the file");
        }
    }

    private Arena parseChecked() {
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
            throw error(1, "expected '" + ArenaFormat.HEADER + "', found no content; start the file with the line '"
                    + ArenaFormat.HEADER + "'");
        }
        if (sizeLine == 0) {
            throw error(headerLine, "no 'size' line; add 'size <width> <height>' in mm after the header,"
                    + " e.g. 'size 1219.2 1219.2'");
        }
        if (robots.isEmpty() && worldRobot != null) {
            robots.add(worldRobot); // the WSU world's start pose, unless the file gives its own
            robotLines.add(worldLine);
            robotKinds.add(RobotKind.DEFAULT);
        }
        if (robots.isEmpty()) {
            throw error(headerLine, "no 'robot' line; add at least one start pose"
                    + " 'robot <x> <y> <heading>', e.g. 'robot 609.6 609.6 90'");
        }
        checkInside();
        checkWallArea();
        checkTasks();
        Assignment assignment = new Assignment(tasks, timeLimit);
        Arena arena = build(headerLine, () -> new Arena(name != null ? name : nameFromSource(),
                width, height, robots, walls, lights, caps, regions, assignment, robotKinds));
        RobotClearance.check(arena, robotLines, source);
        return arena;
    }

    /** {@code robot x y heading [TYPE]}: TYPE a bundled robot's name or a robot file's path, relative to this file. */
    private void robot(String[] t) {
        RobotKind kind = RobotKind.DEFAULT;
        String[] pose = t;
        if (t.length == 5) {
            String spec = t[4];
            pose = java.util.Arrays.copyOf(t, 4);
            kind = new RobotKind(spec, robotType(spec));
        }
        double[] n = numbers(pose, 1, "robot needs x y heading (3 numbers: mm, mm, degrees) and, if not a khepera1,"
                + " the robot's type (a bundled robot or a robot file)", "x", "y", "heading");
        angle("robot heading", n[2]);
        add(robots, robotLines, build(lineNo, () -> new Pose(n[0], n[1], n[2])), ArenaLimits.MAX_ROBOTS, "robots");
        robotKinds.add(kind);
    }

    private org.kheperasim.sim.engine.robot.RobotType robotType(String spec) {
        if (!org.kheperasim.sim.engine.robot.RobotTypes.BUNDLED.contains(spec) && !spec.contains("/")
                && !spec.endsWith(".yaml")
                && !spec.endsWith(".calibration")) {
            throw error(lineNo, "robot type '" + shorten(spec) + "' is not a bundled robot; use one of "
                    + String.join(", ", org.kheperasim.sim.engine.robot.RobotTypes.BUNDLED)
                    + ", or the path of a robot file (.yaml) or of a calibration (.calibration)");
        }
        try {
            return org.kheperasim.sim.engine.robot.RobotTypes.resolve(spec, folder);
        } catch (org.kheperasim.sim.engine.robot.RobotFileException e) {
            if (e.line() == 0) {
                throw error(lineNo, "robot file '" + shorten(spec) + "': " + e.what());
            }
            throw e;
        }
    }

    private void header(String[] tokens) {
        headerLine = lineNo;
        if (tokens.length == 2 && tokens[0].equals(FORMAT_NAME) && tokens[1].equals(VERSION)) {
            return;
        }
        if (tokens[0].equals(FORMAT_NAME) && tokens.length == 2) {
            throw error(lineNo, "expected '" + ArenaFormat.HEADER + "', found version '" + shorten(tokens[1])
                    + "', which this simulator cannot read; write the file in version " + VERSION);
        }
        throw error(lineNo, "expected '" + ArenaFormat.HEADER + "' as the first line, found '"
                + shorten(String.join(" ", tokens)) + "'; start the file with the line '" + ArenaFormat.HEADER + "'");
    }

    private void item(String[] t) {
        switch (t[0]) {
            case "name" -> name(t);
            case "size" -> size(t);
            case "wsu-world" -> world(t);
            case "robot" -> robot(t);
            case "wall" -> {
                double[] n = numbers(t, 1, "wall needs x1 y1 x2 y2 thickness (5 numbers, mm)",
                        "x1", "y1", "x2", "y2", "thickness");
                atMost("wall thickness", n[4], ArenaLimits.MAX_WALL_THICKNESS_MM, "mm");
                add(walls, wallLines, build(lineNo, () -> new Wall(n[0], n[1], n[2], n[3], n[4])),
                        ArenaLimits.MAX_WALLS, "walls");
            }
            case "light" -> light(t);
            case "cap" -> cap(t);
            case "region" -> region(t);
            case "task" -> add(tasks, taskLines, build(lineNo, () -> TaskLines.parse(t, this::number)),
                    Assignment.MAX_TASKS,
                    "task lines");
            case "time-limit" -> timeLimit(t);
            default -> throw error(lineNo, "unknown keyword '" + shorten(t[0]) + "'; valid keywords are " + KEYWORDS);
        }
    }

    private void name(String[] t) {
        if (nameLine != 0) {
            throw error(lineNo, "a second 'name' line (the first is on line " + nameLine + "); keep one");
        }
        if (t.length != 2 || t[1].length() > 100 || !Region.NAME.matcher(t[1]).matches()) {
            throw error(lineNo, "name needs one word of at most 100 letters, digits, '_' and '-', e.g. 'name maze'");
        }
        name = t[1];
        nameLine = lineNo;
    }

    private void size(String[] t) {
        if (worldLine != 0) {
            throw error(lineNo, "the wsu-world on line " + worldLine + " sets the size; remove this 'size' line");
        }
        if (sizeLine != 0) {
            throw error(lineNo, "a second 'size' line (the first is on line " + sizeLine + "); keep one");
        }
        double[] n = numbers(t, 1, "size needs width height (2 numbers, mm)", "width", "height");
        build(lineNo, () -> Numbers.positive("arena width", n[0], "mm"));
        build(lineNo, () -> Numbers.positive("arena height", n[1], "mm"));
        build(lineNo, () -> {
            ArenaLimits.checkSize(n[0], n[1]);
            return null;
        });
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
                if (TokenNumbers.NUMBER.matcher(t[i]).matches()) {
                    throw error(lineNo, "light has a number '" + shorten(t[i]) + "' where a keyword belongs;"
                            + " after x y write keyword-value pairs such as 'range 400' (" + LIGHT_KEYWORDS + ")");
                }
                throw error(lineNo, "unknown light keyword '" + shorten(t[i]) + "'; valid light keywords are "
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
        atMost("light range", opt[0], ArenaLimits.MAX_LIGHT_RANGE_MM, "mm");
        atMost("light intensity", opt[1], ArenaLimits.MAX_LIGHT_INTENSITY, "(1 is the standard lamp)");
        atMost("light radius", opt[2], ArenaLimits.MAX_LIGHT_RADIUS_MM, "mm");
        angle("light direction", opt[3]);
        add(lights, lightLines, build(lineNo, () -> new Light(x, y, opt[2], opt[0], opt[1], opt[3], opt[4])),
                ArenaLimits.MAX_LIGHTS, "lights");
    }

    private void cap(String[] t) {
        String usage = "cap needs x y, optionally followed by 'radius <mm>'";
        if (t.length == 5 && !t[3].equals("radius") && !TokenNumbers.NUMBER.matcher(t[3]).matches()) {
            throw error(lineNo, "unknown cap keyword '" + shorten(t[3]) + "'; the only cap keyword is radius");
        }
        if (t.length != 3 && !(t.length == 5 && t[3].equals("radius"))) {
            throw error(lineNo, usage + ", got " + (t.length - 1) + " values");
        }
        double x = number(t[1], "cap x");
        double y = number(t[2], "cap y");
        double r = t.length == 5 ? number(t[4], "cap radius") : Cap.DEFAULT_RADIUS;
        atMost("cap radius", r, ArenaLimits.MAX_CAP_RADIUS_MM, "mm");
        add(caps, capLines, build(lineNo, () -> new Cap(x, y, r)), ArenaLimits.MAX_CAPS, "caps");
    }

    private void region(String[] t) {
        count(regions.size(), ArenaLimits.MAX_REGIONS, "regions");
        String usage = "region needs name x1 y1 x2 y2 (a name and 4 numbers, mm)";
        if (t.length != 6) {
            throw error(lineNo, usage + ", got " + (t.length - 1) + " values");
        }
        if (t[1].length() > 100) {
            throw error(lineNo, "region name '" + shorten(t[1]) + "' is longer than 100 characters; shorten it");
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

    private void timeLimit(String[] t) {
        if (timeLimitLine != 0) {
            throw error(lineNo, "a second 'time-limit' line (the first is on line " + timeLimitLine + "); keep one");
        }
        double[] n = numbers(t, 1,
                "time-limit needs the simulated seconds a run gets (1 number, s), e.g. 'time-limit 600'",
                "seconds");
        if (!(n[0] > 0)) {
            throw error(lineNo, "time-limit is " + Numbers.brief(n[0])
                    + " s; give a positive number of simulated seconds");
        }
        build(lineNo, () -> new Assignment(List.of(), n[0]));
        timeLimit = n[0];
        timeLimitLine = lineNo;
    }

    /**
     * {@code wsu-world PATH}: the world's size, walls, lamps and caps, and its start pose unless robot lines follow.
     */
    private void world(String[] t) {
        if (worldLine != 0 || sizeLine != 0) {
            throw error(lineNo, worldLine != 0 ? "a second 'wsu-world' line (the first is on line " + worldLine
                    + "); an arena builds on one world" : "wsu-world sets the size, and line " + sizeLine
                    + " set it already; remove the 'size' line");
        }
        if (t.length < 2) {
            throw error(lineNo, "wsu-world needs the path of a WSU world file, e.g. 'wsu-world maze'");
        }
        Arena w = WsuWorldBase.read(String.join(" ", Arrays.copyOfRange(t, 1, t.length)), folder, source, lineNo);
        worldLine = lineNo;
        sizeLine = lineNo;
        width = w.width();
        height = w.height();
        worldRobot = w.robots().get(0);
        w.walls().forEach(x -> add(walls, wallLines, x, ArenaLimits.MAX_WALLS, "walls"));
        w.lights().forEach(x -> add(lights, lightLines, x, ArenaLimits.MAX_LIGHTS, "lights"));
        w.caps().forEach(x -> add(caps, capLines, x, ArenaLimits.MAX_CAPS, "caps"));
    }

    private <T> void add(List<T> items, List<Integer> itemLines, T item, int max, String what) {
        count(items.size(), max, what);
        items.add(item);
        itemLines.add(lineNo);
    }

    private void checkTasks() {
        for (int i = 0; i < tasks.size(); i++) {
            String wrong = TaskLines.check(tasks.get(i), regions, caps.size());
            if (wrong != null) {
                throw error(taskLines.get(i), wrong);
            }
        }
    }

    private void count(int sofar, int max, String what) {
        if (sofar >= max) {
            throw error(lineNo, "too many " + what + ": an arena may have at most " + max + "; remove " + what
                    + " from here on");
        }
    }

    private void atMost(String what, double value, double max, String unit) {
        if (value > max) {
            throw error(lineNo, what + " is " + Numbers.brief(value) + "; it may be at most "
                    + Numbers.brief(max) + " " + unit);
        }
    }

    private void angle(String what, double deg) {
        if (deg < -MAX_ANGLE_DEG || deg > MAX_ANGLE_DEG) {
            throw error(lineNo, what + " is " + Numbers.brief(deg) + " degrees; give an angle from -360 to 360");
        }
    }

    /** Parses {@code t[from..]} as exactly {@code fields.length} numbers. */
    private double[] numbers(String[] t, int from, String usage, String... fields) {
        return tokens.numbers(t, from, usage, lineNo, fields);
    }

    private double number(String token, String what) {
        return tokens.number(token, what, lineNo);
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
        new ArenaBounds(source, width, height).inside(what, x, y, line);
    }

    private void checkWallArea() {
        new ArenaBounds(source, width, height).wallArea(walls, wallLines);
    }

    private String nameFromSource() {
        String base = source.substring(Math.max(source.lastIndexOf('/'), source.lastIndexOf('\\')) + 1);
        if (base.endsWith(ArenaFormat.EXTENSION)) {
            base = base.substring(0, base.length() - ArenaFormat.EXTENSION.length());
        }
        base = base.replaceAll("[^A-Za-z0-9_-]", "_");
        if (base.length() > 100) {
            base = base.substring(0, 100);
        }
        return base.isEmpty() ? "arena" : base;
    }

    private <T> T build(int line, Supplier<T> constructor) {
        try {
            return constructor.get();
        } catch (IllegalArgumentException e) {
            throw error(line, e.getMessage());
        }
    }

    private ArenaFormatException error(int line, String... what) {
        return new ArenaFormatException(source, line, String.join("", what));
    }

    private static String shorten(String token) {
        return TokenNumbers.shorten(token);
    }
}
