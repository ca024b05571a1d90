package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.wsu.WsuWorld;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * The course pairings under {@code --set profile=wsu}, 60 simulated seconds, seed 1, beside the
 * original's figures (KSuite 1.1.2 and the fork, from their own recorders, issue 38): the table
 * "The wsu profile" of docs/wsu-migration.md. Needs the public course code, as
 * {@link WsuCorpusTest} does ({@code -Dkheperasim.wsuCorpus=DIR}, here with the clones of
 * Nepetalactone/Systemarchitekturen-FHV, christianLins/KheperaRobotControl, Habitats/khepera (its
 * maps) and Elliot-TS/Modified-WSU-Khepera-Simulator); skipped without it.
 */
class WsuProfileCorpusTest {
    private static final Settings WSU = Settings.defaults().with("profile", "wsu");

    private static Path corpus;

    @TempDir
    static Path dir;

    @BeforeAll
    static void findTheCorpus() {
        String p = System.getProperty(WsuCorpusTest.PROPERTY);
        Assumptions.assumeTrue(p != null && !p.isBlank(), "no -D" + WsuCorpusTest.PROPERTY + "=DIR: the public course code is not here");
        corpus = Path.of(p);
    }

    private static Path compile(String folder) throws IOException {
        Path src = corpus.resolve(folder);
        Assumptions.assumeTrue(Files.isDirectory(src), src + " is not in the corpus");
        Path out = Files.createDirectories(dir.resolve(folder.replace('/', '_')));
        List<String> args = new ArrayList<>(List.of("-nowarn", "-encoding", "ISO-8859-1", "-proc:none", "--release", "17",
                "-cp", System.getProperty("java.class.path"), "-d", out.toString()));
        try (Stream<Path> files = Files.walk(src)) {
            files.filter(f -> f.toString().endsWith(".java"))
                    .filter(f -> !src.relativize(f).toString().replace('\\', '/').startsWith("edu/wsu/KheperaSimulator/"))
                    .forEach(f -> args.add(f.toString()));
        }
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, quiet, quiet, args.toArray(new String[0])),
                folder + " compiles unchanged");
        return out;
    }

    /** What a minute did: the robot every 50 ms, the caps at the start and the end. */
    record Minute(RunResult result, List<RobotView> robot, List<CapView> capsAtStart, List<CapView> capsAtEnd) {
        double metres() {
            return result.first().distanceMm() / 1000;
        }

        RobotView first() {
            return robot.get(0);
        }

        RobotView last() {
            return robot.get(robot.size() - 1);
        }

        /** @return how far the cap that moved most moved, mm */
        double ballMovedMm() {
            double most = 0;
            for (int i = 0; i < capsAtStart.size(); i++) {
                CapView a = capsAtStart.get(i);
                CapView b = capsAtEnd.get(i);
                most = Math.max(most, Math.hypot(b.x() - a.x(), b.y() - a.y()));
            }
            return most;
        }
    }

    static Minute minute(Path classes, String map, String controller, Settings settings) {
        return minute(classes, map, controller, settings, 1);
    }

    static Minute minute(Path classes, String map, String controller, Settings settings, long seed) {
        Path file = corpus.resolve("khepera/maps").resolve(map);
        Arena arena = WsuWorld.read(file, note -> { });
        List<RobotView> robot = new CopyOnWriteArrayList<>();
        List<List<CapView>> caps = new CopyOnWriteArrayList<>();
        RunResult r = Simulation.builder().arena(arena).classpath(List.of(classes)).controller(controller)
                .seed(seed).seconds(60).settings(settings).console(l -> { })
                .listener(s -> {
                    robot.add(s.robots().get(0));
                    caps.add(s.caps());
                }, 50).run();
        assertFalse(r.first().status().failed(), controller + " runs its minute: " + r.first());
        return new Minute(r, robot, caps.get(0), caps.get(caps.size() - 1));
    }

    private static void print(String what, Minute wsu, Minute robot, String original) {
        System.out.printf(Locale.ROOT, "%s: profile wsu %.2f m (ball %.0f mm, ends %.0f mm E, %.0f mm N of its start);"
                + " default %.2f m (ball %.0f mm); original %s%n", what, wsu.metres(), wsu.ballMovedMm(),
                wsu.last().x() - wsu.first().x(), wsu.last().y() - wsu.first().y(), robot.metres(), robot.ballMovedMm(), original);
    }

    @Test
    void followThatWallSticksInTheFirstCornerAsInTheOriginal() throws IOException {
        Path c = compile("Systemarchitekturen-FHV/ue4/WSU_KSuite_1.1.2/src");
        Minute wsu = minute(c, "passage", "FollowThatWall", WSU);
        print("FollowThatWall, passage", wsu, minute(c, "passage", "FollowThatWall", Settings.defaults()), "0.27 m both runs");
        assertTrue(wsu.metres() <= 0.5, "at most 0.5 m: " + wsu.result().first());
        // The original drives about 0.27 m east from its start into the corner and stays there.
        double off = Math.hypot(wsu.last().x() - (wsu.first().x() + 270), wsu.last().y() - wsu.first().y());
        assertTrue(off <= 100, "ends within 100 mm of where the original stops: " + off + " mm away");
    }

    /**
     * The original's outcome varies from run to run (its loop ran on the desktop's clock): measured
     * there, the ball moved 663, 149 and 731 mm in three runs (issue 38's own three: 269-522). Under
     * the profile the loop's pauses follow that clock's measured distribution, drawn from the seed,
     * so the outcome varies from seed to seed: over seeds 1-10 the ball must move 150 mm or more at
     * the median and in at least half of the runs.
     */
    @Test
    void pushBallsToLightPushesTheBall() throws IOException {
        Path c = compile("KheperaRobotControl/RobotControl1/src");
        List<Double> moved = new ArrayList<>();
        for (int seed = 1; seed <= 10; seed++) {
            moved.add(minute(c, "behavior2-minefield", "PushBallsToLightController", WSU, seed).ballMovedMm());
        }
        Minute robot = minute(c, "behavior2-minefield", "PushBallsToLightController", Settings.defaults(), 1);
        System.out.printf(Locale.ROOT, "PushBallsToLight, behavior2-minefield: profile wsu, seeds 1-10, ball moved %s mm;"
                + " default (seed 1) %.0f mm; original 663, 149, 731 mm (3 runs)%n", moved.stream()
                .map(m -> String.format(Locale.ROOT, "%.0f", m)).toList(), robot.ballMovedMm());
        List<Double> sorted = moved.stream().sorted().toList();
        double median = (sorted.get(4) + sorted.get(5)) / 2;
        assertTrue(median >= 150, "the ball moves at least 150 mm at the median: " + moved);
        assertTrue(moved.stream().filter(m -> m >= 150).count() >= 5, "and in at least half the runs: " + moved);
    }

    @Test
    void driveAlongWallMoves() throws IOException {
        Path c = compile("KheperaRobotControl/RobotControl1/src");
        Minute wsu = minute(c, "sensors1-compartments", "DriveAlongWallProportionalController", WSU);
        print("DriveAlongWallProportional, sensors1-compartments", wsu,
                minute(c, "sensors1-compartments", "DriveAlongWallProportionalController", Settings.defaults()), "1.16 m, 0.46 m");
        assertTrue(wsu.metres() >= 0.3, "at least 0.3 m: " + wsu.result().first());
    }

    @Test
    void basicReactiveTravelsAsFarAsInTheOriginal() throws IOException {
        Path c = compile("Modified-WSU-Khepera-Simulator/source");
        Minute wsu = minute(c, "maze", "basic_reactive", WSU);
        print("basic_reactive, maze", wsu, minute(c, "maze", "basic_reactive", Settings.defaults()), "7.5 m, 6.8 m");
        double mean = (7.5 + 6.8) / 2;
        assertTrue(Math.abs(wsu.metres() - mean) <= 0.25 * mean, "within 25 % of 7.15 m: " + wsu.metres());
    }
}
