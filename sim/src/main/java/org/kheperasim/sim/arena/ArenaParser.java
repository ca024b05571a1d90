package org.kheperasim.sim.arena;

import static org.kheperasim.sim.arena.ArenaLimits.MAX_ANGLE_DEG;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
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
    private static final String KEYWORDS = "name, size, robot, wall, light, cap, region, task, time-limit";
    private static final String LIGHT_KEYWORDS = "range, intensity, radius, direction, spread";
    /** Possessive quantifiers: a long run of digits cannot make the match backtrack. */
    static final Pattern NUMBER = Pattern.compile("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+");
    private static final Pattern NOT_FINITE = Pattern.compile("[+-]?(nan|inf|infinity)", Pattern.CASE_INSENSITIVE);
    private static final Pattern LINE_BREAK = Pattern.compile("\r\n|\r|\n");
    private static final Pattern BLANKS = Pattern.compile("\\s+");

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
    private final List<Task> tasks = new ArrayList<>();
    private final List<Integer> taskLines = new ArrayList<>();
    private double timeLimit;
    private int timeLimitLine;

    ArenaParser(String text, String source) {
        this.source = source;
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
        if (robots.isEmpty()) {
            throw error(headerLine, "no 'robot' line; add at least one start pose"
                    + " 'robot <x> <y> <heading>', e.g. 'robot 609.6 609.6 90'");
        }
        checkInside();
        checkWallArea();
        checkTasks();
        Assignment assignment = new Assignment(tasks, timeLimit);
        Arena arena = build(headerLine, () -> new Arena(name != null ? name : nameFromSource(),
                width, height, robots, walls, lights, caps, regions, assignment));
        RobotClearance.check(arena, robotLines, source);
        return arena;
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
            case "robot" -> {
                count(robots.size(), ArenaLimits.MAX_ROBOTS, "robots");
                double[] n = numbers(t, 1, "robot needs x y heading (3 numbers: mm, mm, degrees)",
                        "x", "y", "heading");
                angle("robot heading", n[2]);
                robots.add(build(lineNo, () -> new Pose(n[0], n[1], n[2])));
                robotLines.add(lineNo);
            }
            case "wall" -> {
                count(walls.size(), ArenaLimits.MAX_WALLS, "walls");
                double[] n = numbers(t, 1, "wall needs x1 y1 x2 y2 thickness (5 numbers, mm)",
                        "x1", "y1", "x2", "y2", "thickness");
                atMost("wall thickness", n[4], ArenaLimits.MAX_WALL_THICKNESS_MM, "mm");
                walls.add(build(lineNo, () -> new Wall(n[0], n[1], n[2], n[3], n[4])));
                wallLines.add(lineNo);
            }
            case "light" -> light(t);
            case "cap" -> cap(t);
            case "region" -> region(t);
            case "task" -> {
                count(tasks.size(), Assignment.MAX_TASKS, "task lines");
                tasks.add(build(lineNo, () -> TaskLines.parse(t, this::number)));
                taskLines.add(lineNo);
            }
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
        count(lights.size(), ArenaLimits.MAX_LIGHTS, "lights");
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
        lights.add(build(lineNo, () -> new Light(x, y, opt[2], opt[0], opt[1], opt[3], opt[4])));
        lightLines.add(lineNo);
    }

    private void cap(String[] t) {
        count(caps.size(), ArenaLimits.MAX_CAPS, "caps");
        String usage = "cap needs x y, optionally followed by 'radius <mm>'";
        if (t.length == 5 && !t[3].equals("radius") && !NUMBER.matcher(t[3]).matches()) {
            throw error(lineNo, "unknown cap keyword '" + shorten(t[3]) + "'; the only cap keyword is radius");
        }
        if (t.length != 3 && !(t.length == 5 && t[3].equals("radius"))) {
            throw error(lineNo, usage + ", got " + (t.length - 1) + " values");
        }
        double x = number(t[1], "cap x");
        double y = number(t[2], "cap y");
        double r = t.length == 5 ? number(t[4], "cap radius") : Cap.DEFAULT_RADIUS;
        atMost("cap radius", r, ArenaLimits.MAX_CAP_RADIUS_MM, "mm");
        caps.add(build(lineNo, () -> new Cap(x, y, r)));
        capLines.add(lineNo);
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
        double[] n = numbers(t, 1, "time-limit needs the simulated seconds a run gets (1 number, s), e.g. 'time-limit 600'",
                "seconds");
        if (!(n[0] > 0)) {
            throw error(lineNo, "time-limit is " + Numbers.brief(n[0]) + " s; give a positive number of simulated seconds");
        }
        build(lineNo, () -> new Assignment(List.of(), n[0]));
        timeLimit = n[0];
        timeLimitLine = lineNo;
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
        if (token.length() > ArenaLimits.MAX_NUMBER_CHARS) {
            throw error(lineNo, what + " is '" + shorten(token) + "', longer than " + ArenaLimits.MAX_NUMBER_CHARS
                    + " characters; write a decimal number such as 12.5");
        }
        if (NUMBER.matcher(token).matches()) {
            double d = Double.parseDouble(token);
            if (Double.isFinite(d)) {
                return d;
            }
            throw error(lineNo, what + " is '" + shorten(token) + "', too large to be a number of mm; give a finite number");
        }
        if (NOT_FINITE.matcher(token).matches()) {
            throw error(lineNo, what + " is '" + token + "'; give a finite number such as 12.5");
        }
        throw error(lineNo, what + " is '" + shorten(token) + "', not a number; write a decimal number such as 12.5");
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
            String w = Numbers.brief(width);
            String h = Numbers.brief(height);
            throw error(line, what + " at " + point(x, y) + " lies outside the " + w + " x " + h
                    + " mm arena; keep x within 0..", w, " and y within 0..", h);
        }
    }

    /**
     * Refuses walls whose areas (length x thickness) add up to more than
     * {@link ArenaLimits#MAX_WALL_AREA_RATIO} times the floor: drawing them would take too long.
     */
    private void checkWallArea() {
        double floor = width * height;
        double total = 0;
        for (int i = 0; i < walls.size(); i++) {
            Wall w = walls.get(i);
            total += (StrictMath.hypot(w.x2() - w.x1(), w.y2() - w.y1()) + w.thickness()) * w.thickness();
            if (total > ArenaLimits.MAX_WALL_AREA_RATIO * floor) {
                throw error(wallLines.get(i), String.format(Locale.ROOT, "the walls up to this one cover %.1f times"
                        + " the floor's area (each wall counts (length + thickness) x thickness); at most %s times"
                        + " is allowed, so remove walls that overlap or make them thinner", total / floor,
                        Numbers.brief(ArenaLimits.MAX_WALL_AREA_RATIO)));
            }
        }
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

    /** A token as quoted in a message: at most 40 characters. */
    private static String shorten(String token) {
        return token.length() <= 40 ? token : token.substring(0, 37) + "...";
    }

    private static String point(double x, double y) {
        return "(" + Numbers.brief(x) + ", " + Numbers.brief(y) + ")";
    }
}
