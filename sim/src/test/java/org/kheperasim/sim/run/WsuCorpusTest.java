package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.arena.wsu.WsuWorld;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * Public course code written for the WSU simulator, compiled unchanged and run on its own maps: the
 * figures of docs/wsu-migration.md ("Course code measured").
 *
 * <p>The code is not part of this project. Give the folder holding clones of the three public
 * repositories as the system property {@value #PROPERTY} ({@code -Dkheperasim.wsuCorpus=DIR}, DIR
 * holding {@code khepera} (github.com/Habitats/khepera), {@code Systemarchitekturen-FHV}
 * (github.com/Nepetalactone/Systemarchitekturen-FHV) and {@code KheperaRobotControl}
 * (github.com/christianLins/KheperaRobotControl)); without it the test is skipped. The original
 * simulator's own classes that some of these folders carry ({@code edu/wsu/KheperaSimulator}) are
 * left out of the compile: the simulator's WSU API stands in for them, as it does for students.
 */
class WsuCorpusTest {
    static final String PROPERTY = "kheperasim.wsuCorpus";

    /** The course sets: a name and the source folder, relative to the corpus folder. */
    private static final Map<String, String> SETS = Map.of(
            "habitats", "khepera/src",
            "fhv-ue4", "Systemarchitekturen-FHV/ue4/WSU_KSuite_1.1.2/src",
            "fhv-ue4-source", "Systemarchitekturen-FHV/ue4/WSU_KSuite_1.1.2/source",
            "fhv-ue5", "Systemarchitekturen-FHV/ue5/RobotControl/src",
            "fhv-ue5-source", "Systemarchitekturen-FHV/ue5/RobotControl/source",
            "lins", "KheperaRobotControl/RobotControl1/src");

    private static Path corpus;
    private static Path maps;

    @TempDir
    static Path dir;

    @BeforeAll
    static void findTheCorpus() {
        String p = System.getProperty(PROPERTY);
        Assumptions.assumeTrue(p != null && !p.isBlank(), "no -D" + PROPERTY + "=DIR: the public course code is not here");
        corpus = Path.of(p);
        maps = corpus.resolve("khepera/maps");
    }

    /** Compiles one set unchanged against the simulator's classes; returns the class folder. */
    private static Path compile(String set) throws IOException {
        Path src = corpus.resolve(SETS.get(set));
        Path out = Files.createDirectories(dir.resolve(set));
        List<String> args = new ArrayList<>(List.of("-nowarn", "-encoding", "ISO-8859-1", "-proc:none", "-cp",
                System.getProperty("java.class.path"), "-d", out.toString()));
        try (Stream<Path> files = Files.walk(src)) {
            files.filter(f -> f.toString().endsWith(".java"))
                    .filter(f -> !src.relativize(f).toString().replace('\\', '/').startsWith("edu/wsu/KheperaSimulator/"))
                    .forEach(f -> args.add(f.toString()));
        }
        StringWriter errors = new StringWriter();
        int rc = ToolProvider.getSystemJavaCompiler().run(null, null, new java.io.PrintStream(
                new java.io.OutputStream() {
                    @Override
                    public void write(int b) {
                        errors.write(b);
                    }
                }), args.toArray(new String[0]));
        assertEquals(0, rc, set + " compiles unchanged: " + errors);
        return out;
    }

    @Test
    void everySetCompilesUnchanged() throws IOException {
        for (String set : SETS.keySet()) {
            if (Files.isDirectory(corpus.resolve(SETS.get(set)))) {
                compile(set);
            }
        }
    }

    /** What a 60 s run did: its samples every 50 ms, the caps at the start and the end. */
    private record Run(RunResult result, List<RobotView> robot, List<CapView> capsAtStart, List<CapView> capsAtEnd, Arena arena) {
        double metres() {
            return result.first().distanceMm() / 1000;
        }

        /** @return the share of samples with a wall within mm of the robot's body */
        double nearWall(double mm) {
            long near = robot.stream().filter(r -> gap(arena, r.x(), r.y()) <= mm).count();
            return near / (double) robot.size();
        }
    }

    private static double gap(Arena arena, double x, double y) {
        double best = Double.MAX_VALUE;
        for (Wall w : arena.walls()) {
            double dx = w.x2() - w.x1();
            double dy = w.y2() - w.y1();
            double l2 = dx * dx + dy * dy;
            double t = l2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - w.x1()) * dx + (y - w.y1()) * dy) / l2));
            best = Math.min(best, Math.hypot(x - (w.x1() + t * dx), y - (w.y1() + t * dy)) - w.thickness() / 2);
        }
        return best - RobotTypes.KHEPERA1.body().radiusMm();
    }

    private static Run run(Path classes, String map, String controller, Settings settings) {
        Arena arena = WsuWorld.read(maps.resolve(map), note -> { });
        List<RobotView> robot = new CopyOnWriteArrayList<>();
        List<List<CapView>> caps = new CopyOnWriteArrayList<>();
        RunResult r = Simulation.builder().arena(arena).classpath(List.of(classes)).controller(controller)
                .seed(1).seconds(60).settings(settings).console(l -> { })
                .listener(s -> {
                    robot.add(s.robots().get(0));
                    caps.add(s.caps());
                }, 50).run();
        assertFalse(r.first().status().failed(), controller + " runs its minute: " + r.first());
        return new Run(r, robot, caps.get(0), caps.get(caps.size() - 1), arena);
    }

    private static double nearestLamp(Arena arena, double x, double y, int[] which) {
        double best = Double.MAX_VALUE;
        for (int i = 0; i < arena.lights().size(); i++) {
            Light l = arena.lights().get(i);
            double d = Math.hypot(l.x() - x, l.y() - y);
            if (d < best) {
                best = d;
                which[0] = i;
            }
        }
        return best;
    }

    @Test
    void followThatWallFollowsThePassagesWalls() throws IOException {
        Run r = run(compile("fhv-ue4"), "passage", "FollowThatWall", Settings.defaults());
        System.out.printf("FollowThatWall on passage: %.2f m, a wall within 60 mm %.0f%% of the time%n",
                r.metres(), 100 * r.nearWall(60));
        assertTrue(r.metres() >= 0.5, "travels at least 0.5 m: " + r.result().first());
        assertTrue(r.nearWall(60) >= 0.5, "a wall within 60 mm at least half the time: " + r.nearWall(60));
    }

    @Test
    void driveAlongWallProportionalTravelsWithTheOriginalsSteadyReadings() throws IOException {
        Path lins = compile("lins");
        Run noisy = run(lins, "sensors1-compartments", "DriveAlongWallProportionalController", Settings.defaults());
        Run steady = run(lins, "sensors1-compartments", "DriveAlongWallProportionalController",
                Settings.defaults().with("noise.reading", "0"));
        System.out.printf("DriveAlongWallProportionalController on sensors1-compartments: %.2f m (defaults), %.2f m"
                + " (noise.reading=0)%n", noisy.metres(), steady.metres());
        // Its deadlock detector waits for every reading to stand still for 200 loops before it moves
        // the robot; the original's readings stood still, real (and default simulated) ones do not.
        assertTrue(steady.metres() >= 0.5, "with steady readings it travels at least 0.5 m: " + steady.result().first());
    }

    @Test
    void hitTheLightsStaysAtItsStartLampAsInTheOriginal() throws IOException {
        Run r = run(compile("fhv-ue4"), "behavior1-gates1", "HitTheLights", Settings.defaults());
        int[] start = new int[1];
        int[] end = new int[1];
        RobotView first = r.robot().get(0);
        RobotView last = r.robot().get(r.robot().size() - 1);
        nearestLamp(r.arena(), first.x(), first.y(), start);
        double d = nearestLamp(r.arena(), last.x(), last.y(), end);
        System.out.printf("HitTheLights on behavior1-gates1: starts by lamp %d, ends %.0f mm from lamp %d, %.2f m%n",
                start[0], d, end[0], r.metres());
    }

    @Test
    void pushBallsToLightRuns() throws IOException {
        Run r = run(compile("lins"), "behavior2-minefield", "PushBallsToLightController", Settings.defaults());
        CapView a = r.capsAtStart().get(0);
        CapView b = r.capsAtEnd().get(0);
        double toward = Double.NEGATIVE_INFINITY;
        for (Light l : r.arena().lights()) {
            toward = Math.max(toward, Math.hypot(a.x() - l.x(), a.y() - l.y()) - Math.hypot(b.x() - l.x(), b.y() - l.y()));
        }
        System.out.printf("PushBallsToLightController on behavior2-minefield: ball moved %.0f mm, %.0f mm nearer a lamp;"
                + " robot %.2f m%n", Math.hypot(b.x() - a.x(), b.y() - a.y()), toward, r.metres());
    }
}
