package org.kheperasim.sim.grade;

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
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * Honest controllers that read the K213 vision turret every step (the student API's
 * {@code vision().getImage()}, WSU KSuite's {@code readLvtImage()}) are graded ok, each run with the
 * score {@code run} gives it, made once: the replay of their command logs takes the turret's images
 * where the runs took them. Before, every such run was called tampered. In the sandbox where there is
 * one; tagged timing, so {@code .ci/run}'s busy pass grades them again beside two busy loops.
 */
@Tag("timing")
class TurretGradingTest {
    private static final String SEEKER = """
            import org.kheperasim.api.*;

            public class Seeker extends Controller {
                @Override
                protected void doWork() {
                    int[] image = vision().getImage();
                    int sum = 0, weight = 0;
                    for (int i = 0; i < image.length; i++) {
                        sum += i * image[i];
                        weight += image[i];
                    }
                    int turn = weight == 0 ? 0 : (int) Math.round((sum / (double) weight - 31.5) / 8);
                    if (proximity(IrSensor.FRONT_LEFT) > 600 || proximity(IrSensor.FRONT_RIGHT) > 600) {
                        setSpeeds(-3, 3);
                    } else {
                        setSpeeds(4 + turn, 4 - turn);
                    }
                    sleepMillis(30);
                }
            }
            """;

    private static final String WSU = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Lvt extends RobotController {
                public Lvt() { }

                public void doWork() throws Exception {
                    float[] image = readLvtImage();
                    float left = 0, right = 0;
                    for (int i = 0; i < image.length; i++) {
                        if (i < 32) { left += image[i]; } else { right += image[i]; }
                    }
                    if (getPixelMaxIntensity() > 250) {
                        setMotorSpeeds(left > right ? 2 : 5, left > right ? 5 : 2);
                    } else {
                        setMotorSpeeds(4, 4);
                    }
                    sleep(40);
                }

                public void close() throws Exception { }
            }
            """;

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 400, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void turretReadersAreGradedOkWithTheScoreRunGives() throws IOException {
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        if ("true".equals(System.getenv("CI"))) {
            Hostile.requireBox();
        }
        Path subs = dir.resolve("subs");
        write(subs.resolve("vera"), "Seeker", SEEKER);
        write(subs.resolve("walt"), "Lvt", WSU);
        Path out = dir.resolve("out");
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("beacon-maze"), 2, 2, out, GradePlan.Shard.ALL,
                256, 200, 5, 20.0, false, new PrintStream(OutputStream.nullOutputStream()), false, box, false));
        Arena arena = ArenaFormat.resolve("beacon-maze");
        for (RunRecord r : report.runs()) {
            assertEquals(RunStatus.OK, r.status(), r.toString());
            assertFalse(r.madeAgain(), "made once: " + r);
            Path classes = compiled(subs.resolve(r.student()), r.controller());
            RunResult run = Simulation.builder().arena("beacon-maze").classpath(List.of(classes)).controller(r.controller())
                    .seed(r.seed()).seconds(20).run();
            Score score = Score.of(arena, RunFacts.of(run));
            assertEquals(score.points(), r.points(), 0.005, "the score run gives: " + r);
        }
        assertEquals(4, report.runs().size());
        String table = Files.readString(out.resolve("report.txt"));
        assertTrue(table.contains("; 0 reruns"), table);
    }

    /**
     * Three robots in one arena, each with the student's thread controller (a thread-style one that
     * thinks now and then, a step controller), over two seeds: each run graded ok, made once, with
     * the score {@code run} gives.
     */
    @Test
    @Timeout(value = 400, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void threeRobotsAreGradedOkWithTheScoreRunGivesOverSeveralSeeds() throws IOException {
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        if ("true".equals(System.getenv("CI"))) {
            Hostile.requireBox();
        }
        Path arenaFile = dir.resolve("three.arena");
        Files.writeString(arenaFile, Files.readString(Path.of("../arenas/lab.arena")).replace("robot 609.6 609.6 90",
                "robot 300 300 0\nrobot 900 300 90\nrobot 600 900 180"));
        Path subs = dir.resolve("subs");
        write(subs.resolve("tess"), "Thinker", THINKER);
        write(subs.resolve("stan"), "Stepper", STEPPER);
        Path out = dir.resolve("out");
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of(arenaFile.toString()), 2, 2, out,
                GradePlan.Shard.ALL, 256, 200, 5, 30.0, false, new PrintStream(OutputStream.nullOutputStream()), false, box, false));
        Arena arena = ArenaFormat.resolve(arenaFile.toString());
        assertEquals(4, report.runs().size());
        for (RunRecord r : report.runs()) {
            assertEquals(RunStatus.OK, r.status(), r.toString());
            assertFalse(r.madeAgain(), "made once: " + r);
            RunResult run = Simulation.builder().arena(arena).classpath(List.of(compiled(subs.resolve(r.student()), r.controller())))
                    .controller(r.controller()).seed(r.seed()).seconds(30).run();
            assertEquals(Score.of(arena, RunFacts.of(run)).points(), r.points(), 0.005, "the score run gives: " + r);
        }
    }

    private static final String THINKER = """
            import org.kheperasim.api.*;

            public class Thinker extends Controller {
                private long rounds, thought = 1;

                @Override
                protected void doWork() {
                    int l = Math.max(proximity(IrSensor.LEFT_45), proximity(IrSensor.FRONT_LEFT));
                    int r = Math.max(proximity(IrSensor.RIGHT_45), proximity(IrSensor.FRONT_RIGHT));
                    setSpeeds(l > 500 || r > 500 ? (l >= r ? 3 : -3) : 5, l > 500 || r > 500 ? (l >= r ? -3 : 3) : 4);
                    if (++rounds % 9 == 0) {
                        for (int i = 0; i < 200_000; i++) {
                            thought = thought * 6364136223846793005L + 1442695040888963407L;
                        }
                    }
                    sleepMillis(thought == 0 ? 31 : 30);
                }
            }
            """;

    private static final String STEPPER = """
            import org.kheperasim.api.*;

            public class Stepper extends StepController {
                @Override
                protected void step() {
                    int l = proximity(IrSensor.FRONT_LEFT), r = proximity(IrSensor.FRONT_RIGHT);
                    setSpeeds(l > 600 ? 3 : 5, l > 600 ? -3 : (r > 600 ? 2 : 5));
                }
            }
            """;

    private static void write(Path folder, String name, String source) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve(name + ".java"), source);
    }

    /** Each student's classes, compiled once for all of the student's runs (javac costs more than a run here). */
    private final java.util.Map<Path, Path> compiledFolders = new java.util.HashMap<>();

    private Path compiled(Path folder, String controller) throws IOException {
        Path done = compiledFolders.get(folder);
        if (done != null) {
            return done;
        }
        Path classes = Files.createDirectories(dir.resolve("classes-" + folder.getFileName()));
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "--release", "17", "-proc:none"));
        try (var files = Files.list(folder)) {
            files.filter(f -> f.toString().endsWith(".java")).forEach(f -> args.add(f.toString()));
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])), controller);
        compiledFolders.put(folder, classes);
        return classes;
    }
}
