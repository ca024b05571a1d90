package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.binding.ControllerNames;

/**
 * The allowlist is judged on real code: every bundled controller, the paper's Appendix controller,
 * every Java example of the docs, the WSU course controllers the tests run, and controllers written
 * the way the docs say (records, lambdas, streams, helper threads, a {@code config.properties} of
 * their own, a NetBeans catch block's logger) pass the loader's check unchanged.
 * {@link WsuCorpusAllowlistTest} does the same for the public WSU course code, where it is present.
 */
class AllowlistOnRealCodeTest {
    private static final Path REPO = Path.of(System.getProperty("kheperasim.repoRoot", ".."));

    @TempDir
    Path dir;

    /** Check every class file under {@code classes} with a contained loader; @return the refusals */
    static List<String> refusals(Path classes, List<String> counted) throws IOException {
        List<String> refused = new ArrayList<>();
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), AllowlistOnRealCodeTest.class.getClassLoader());
                Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".class")).sorted().toList()) {
                String name = classes.relativize(f).toString().replace('\\', '/');
                name = name.substring(0, name.length() - ".class".length()).replace('/', '.');
                counted.add(name);
                try {
                    loader.check(name);
                } catch (ControllerPolicyError e) {
                    refused.add(name + ": " + e.getMessage());
                }
            }
        }
        return refused;
    }

    /** Compile sources (file name to text) against the test classpath; @return the class folder */
    static Path compile(Path into, Map<Path, String> sources) throws IOException {
        Path src = Files.createDirectories(into.resolve("src"));
        Path classes = Files.createDirectories(into.resolve("classes"));
        List<String> options = List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "--release", "17", "-proc:none", "-nowarn", "-encoding", "UTF-8");
        List<String> files = new ArrayList<>();
        for (Map.Entry<Path, String> s : sources.entrySet()) {
            Path file = src.resolve(s.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, s.getValue(), StandardCharsets.UTF_8);
            files.add(file.toString());
        }
        StringWriter out = new StringWriter();
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        boolean ok = javac.getTask(out, null, null, options, null,
                javac.getStandardFileManager(null, null, StandardCharsets.UTF_8).getJavaFileObjectsFromStrings(files)).call();
        assertTrue(ok, "the sources compile: " + out);
        return classes;
    }

    @Test
    void everyBundledControllerPasses() throws IOException {
        List<String> refused = new ArrayList<>();
        List<String> names = ControllerNames.bundled(getClass().getClassLoader());
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(), getClass().getClassLoader())) {
            for (String name : names) {
                try {
                    loader.check(ControllerNames.BUNDLED_PACKAGE + "." + name);
                } catch (ControllerPolicyError e) {
                    refused.add(e.getMessage());
                }
            }
        }
        assertEquals(List.of(), refused);
        assertTrue(names.size() >= 8, "the bundled controllers: " + names);
        System.out.println("allowlist: " + names.size() + " bundled controllers pass");
    }

    @Test
    void theAppendixControllerPasses() throws IOException {
        String appendix;
        try (InputStream in = getClass().getResourceAsStream("/appendix/Robot.java.txt")) {
            appendix = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        Path classes = compile(dir, Map.of(Path.of("Robot.java"), "import org.kheperasim.api.*;\n" + appendix));
        List<String> counted = new ArrayList<>();
        assertEquals(List.of(), refusals(classes, counted));
        assertEquals(List.of("Robot"), counted);
    }

    /** A controller class: the student API's or the WSU API's base classes, or the Appendix's Thread. */
    private static final Pattern CONTROLLER = Pattern.compile(
            "extends\\s+(?:Controller|StepController|RobotController|Thread)\\b|implements\\s+.*\\bController\\b");

    @Test
    void everyJavaExampleOfTheDocsPasses() throws IOException {
        List<Path> pages = new ArrayList<>(List.of(REPO.resolve("README.md")));
        try (Stream<Path> docs = Files.list(REPO.resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        Pattern block = Pattern.compile("```java\\n(.*?)```", Pattern.DOTALL);
        Pattern type = Pattern.compile("public\\s+(?:abstract\\s+)?class\\s+(\\w+)");
        List<String> counted = new ArrayList<>();
        List<String> refused = new ArrayList<>();
        int n = 0;
        for (Path page : pages) {
            Matcher m = block.matcher(Files.readString(page));
            while (m.find()) {
                String code = m.group(1).stripIndent();
                Matcher c = type.matcher(code);
                assertTrue(c.find(), page + ": a java block declares a public class");
                if (!CONTROLLER.matcher(code).find()) {
                    continue; // a program using the simulator itself (docs/web-replay.md's), not a controller
                }
                Path classes = compile(dir.resolve("doc" + n++), Map.of(Path.of(c.group(1) + ".java"), code));
                refused.addAll(refusals(classes, counted));
            }
        }
        assertEquals(List.of(), refused);
        assertTrue(counted.size() >= 5, "the docs' examples: " + counted);
    }

    @Test
    void theWsuCourseControllersOfTheTestsPass() throws IOException {
        List<String> names = List.of("WsuAvoider", "WsuCounterTurn", "WsuHelped", "WsuSensorThread", "WsuSlow", "WsuGripper",
                "util/Smoother");
        Map<Path, String> sources = new java.util.HashMap<>();
        for (String s : names) {
            try (InputStream in = getClass().getResourceAsStream("/wsu-course/" + s + ".java")) {
                sources.put(Path.of(s + ".java"), new String(in.readAllBytes(), StandardCharsets.UTF_8));
            }
        }
        List<String> counted = new ArrayList<>();
        assertEquals(List.of(), refusals(compile(dir, sources), counted));
        assertTrue(counted.size() >= names.size(), counted.toString());
    }

    /** Controllers written as the docs and the course material write them. */
    @Test
    void controllersInTheStyleOfTheDocsPass() throws IOException {
        Map<Path, String> sources = Map.of(Path.of("Styled.java"), """
                import org.kheperasim.api.*;
                import java.io.*;
                import java.math.BigDecimal;
                import java.text.DecimalFormat;
                import java.time.*;
                import java.util.*;
                import java.util.concurrent.*;
                import java.util.concurrent.atomic.AtomicInteger;
                import java.util.function.*;
                import java.util.logging.*;
                import java.util.regex.Pattern;
                import java.util.stream.*;

                public class Styled extends Controller {
                    record Reading(int sensor, int value) { }
                    enum Mode { SEEK, AVOID }
                    private final Map<Mode, Integer> visits = new EnumMap<>(Mode.class);
                    private final Queue<Reading> readings = new ConcurrentLinkedQueue<>();
                    private final AtomicInteger steps = new AtomicInteger();
                    private final Object lock = new Object();
                    private final Properties config = new Properties();
                    private Mode mode = Mode.SEEK;

                    public Styled() {
                        try (InputStream in = getClass().getResourceAsStream("config.properties")) {
                            if (in != null) {
                                config.load(in);
                            }
                        } catch (IOException e) {
                            Logger.getLogger(Styled.class.getName()).log(Level.SEVERE, null, e);
                        }
                        InputStream other = Thread.currentThread().getContextClassLoader().getResourceAsStream("route.txt");
                        if (other != null) {
                            try (BufferedReader r = new BufferedReader(new InputStreamReader(other, java.nio.charset.StandardCharsets.UTF_8))) {
                                r.lines().forEach(l -> print(l));
                            } catch (IOException e) {
                                e.printStackTrace();
                            }
                        }
                        Thread watcher = new Thread(() -> {
                            while (isActive()) {
                                synchronized (lock) {
                                    readings.add(new Reading(0, proximity(IrSensor.LEFT_90)));
                                    lock.notifyAll();
                                }
                                try {
                                    TimeUnit.MILLISECONDS.sleep(30);
                                } catch (InterruptedException e) {
                                    return;
                                }
                            }
                        }, "watcher");
                        watcher.setDaemon(true);
                        watcher.start();
                    }

                    @Override
                    protected void doWork() {
                        int[] values = IntStream.range(0, 8).map(i -> sensors()[i].getDistValue()).toArray();
                        int front = Arrays.stream(values, 1, 5).parallel().max().orElse(0);
                        List<Integer> sorted = Arrays.stream(values).boxed().sorted(Comparator.reverseOrder()).collect(Collectors.toList());
                        double mean = sorted.parallelStream().mapToInt(Integer::intValue).average().orElse(0);
                        mode = switch (mode) {
                            case SEEK -> front > 500 ? Mode.AVOID : Mode.SEEK;
                            case AVOID -> front < 300 ? Mode.SEEK : Mode.AVOID;
                        };
                        visits.merge(mode, 1, Integer::sum);
                        Optional<Reading> last = Optional.ofNullable(readings.poll());
                        last.map(Reading::value).filter(v -> v > 900).ifPresent(v -> System.out.println("close: " + v));
                        String line = String.format(Locale.ROOT, "%s %.1f %s", mode, mean, new DecimalFormat("0.00").format(mean));
                        if (Pattern.matches("AVOID.*", line) && steps.incrementAndGet() % 100 == 0) {
                            System.out.printf("%s at %d ms (%s)%n", line, System.currentTimeMillis(), Instant.now());
                        }
                        BigDecimal speed = BigDecimal.valueOf(5).multiply(BigDecimal.ONE);
                        Random random = new Random(42);
                        Function<Integer, Integer> jitter = s -> s + random.nextInt(2);
                        setSpeeds(mode == Mode.AVOID ? 3 : jitter.apply(speed.intValue()), mode == Mode.AVOID ? -3 : 5);
                        StringBuilder report = new StringBuilder().append(visits).append(' ').append(Duration.ofMillis(100));
                        if (report.length() < 0) {
                            throw new IllegalStateException(report.toString());
                        }
                        sleepMillis(100);
                    }
                }
                """);
        List<String> counted = new ArrayList<>();
        assertEquals(List.of(), refusals(compile(dir, sources), counted));
        assertTrue(counted.contains("Styled$Reading") && counted.contains("Styled$Mode"), counted.toString());
    }

    /**
     * What public WSU course code uses, in the patterns it uses them (written here, not copied): the
     * observer pattern, {@code java.awt} points, rectangles, sizes and colours, {@code java.awt.geom}
     * points and lines, and a calendar; and what stays refused, with the reason naming the replacement.
     */
    @Test
    void theValueClassesOfCourseCodePass() throws IOException {
        Map<Path, String> sources = Map.of(Path.of("Mapper.java"), """
                import edu.wsu.KheperaSimulator.RobotController;
                import java.awt.*;
                import java.awt.geom.*;
                import java.util.*;

                public class Mapper extends RobotController implements Observer {
                    static class Grid extends Observable {
                        void mark(Point p) { setChanged(); notifyObservers(p); }
                    }
                    private final Grid grid = new Grid();
                    private final Map<Point, Color> seen = new HashMap<>();
                    private Rectangle bounds = new Rectangle(0, 0, 10, 10);

                    public Mapper() { grid.addObserver(this); }

                    public void update(Observable o, Object arg) {
                        Point p = (Point) arg;
                        bounds = bounds.union(new Rectangle(p, new Dimension(1, 1)));
                        float[] hsb = Color.RGBtoHSB(200, 10, 10, null);
                        seen.put(p, Color.getHSBColor(hsb[0], hsb[1], hsb[2]).brighter());
                    }

                    public void doWork() throws Exception {
                        Point2D here = new Point2D.Double(getLeftWheelPosition(), getRightWheelPosition());
                        Line2D wall = new Line2D.Float(0, 0, 100, 0);
                        Rectangle2D box = wall.getBounds2D();
                        grid.mark(new Point((int) here.getX(), (int) wall.ptSegDist(here)));
                        Calendar c = Calendar.getInstance();
                        c.add(Calendar.SECOND, 1);
                        AffineTransform t = AffineTransform.getRotateInstance(Math.PI / 2);
                        t.transform(here, null);
                        System.out.println(c.get(Calendar.MINUTE) + " " + box.getWidth() + " " + seen.size()
                                + " " + Color.RED.getRGB() + " " + new GregorianCalendar(2001, 6, 27).getTimeInMillis());
                    }

                    public void close() throws Exception { }
                }
                """);
        List<String> counted = new ArrayList<>();
        assertEquals(List.of(), refusals(compile(dir, sources), counted));
        assertTrue(counted.contains("Mapper$Grid"), counted.toString());
    }

    @Test
    void threadPoolsAndTheToolkitStayRefusedNamingTheReplacement() throws IOException {
        Map<Path, String> sources = Map.of(
                Path.of("WallCalendar.java"), """
                public class WallCalendar {
                    long now() { return new java.util.GregorianCalendar().getTimeInMillis() + new java.util.Date().getTime(); }
                }
                """,
                Path.of("Pool.java"), """
                public class Pool {
                    void start(Runnable r) {
                        java.util.concurrent.Executors.newScheduledThreadPool(1)
                                .scheduleAtFixedRate(r, 1, 10, java.util.concurrent.TimeUnit.MILLISECONDS);
                    }
                }
                """,
                Path.of("ColourProperty.java"), """
                public class ColourProperty {
                    java.awt.Color c() { return java.awt.Color.getColor("user.home"); }
                }
                """,
                Path.of("Kit.java"), """
                public class Kit {
                    Object k() { return java.awt.Toolkit.getDefaultToolkit(); }
                }
                """);
        List<String> refused = refusals(compile(dir, sources), new ArrayList<>());
        assertEquals(3, refused.size(), refused.toString());
        String all = String.join("\n", refused);
        // The wall-clock constructors are allowed: what they make is set to the simulated clock (ClockConstructorsTest).
        assertFalse(all.contains("WallCalendar"), all);
        assertTrue(all.contains("Pool.java:3: uses java.util.concurrent.Executors.newScheduledThreadPool(int): thread pools"), all);
        assertTrue(all.contains("for scheduleAtFixedRate, a Thread whose run loops task.run(); Thread.sleep(period)"), all);
        assertTrue(all.contains("ColourProperty.java:2: uses java.awt.Color.getColor(String)"), all);
        assertTrue(all.contains("Kit.java:2: uses java.awt.Toolkit.getDefaultToolkit()"), all);
    }
}
