package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.ball;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.light;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.wsu.WsuWorldWriter;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.host.ConsoleLine;

/**
 * Controllers in the style of later WSU courses, run in the simulator on a WSU world: speeds set in an
 * overridden {@code simStart()} move the robot at time 0; a count-tuned turn turns as its authors saw
 * with {@code wsu.positionUnits=legacy}; the later fork's pose API gives the pose in its units; a
 * controller steering by the K213 vision turret reaches a ball.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuLaterApisRunTest {
    @TempDir
    static Path dir;
    static Path classes;
    static Path world;

    private static final String STARTER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Starter extends RobotController {
                public Starter() { }

                @Override
                public void simStart() {
                    super.simStart();
                    this.setMotorSpeeds(5, 5);
                }

                public void doWork() throws Exception {
                    sleep(500);
                    setMotorSpeeds(-5, 70);                 // 70 is ignored: the right wheel keeps 5
                }

                public void close() throws Exception { }
            }
            """;

    /** Turns right on the spot until the left counter has moved 3 counts a degree, as course helpers do. */
    private static final String TURNER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Turner extends RobotController {
                public Turner() { }

                public void doWork() throws Exception {
                    System.out.println("start " + getRobotXPosition() + " " + getRobotYPosition() + " " + getRobotAngle());
                    long start = getLeftWheelPosition();
                    setMotorSpeeds(2, -2);
                    while (Math.abs(getLeftWheelPosition() - start) / 3 < 45) {
                        sleep(1);
                    }
                    setMotorSpeeds(0, 0);
                    sleep(100);
                    System.out.println("end " + getRobotXPosition() + " " + getRobotYPosition() + " " + getRobotAngle());
                    setFinished(true);
                }

                public void close() throws Exception { }
            }
            """;

    /** A new controller steering by the vision turret: towards the bright (not saturated) pixels, a ball. */
    private static final String BALL_SEEKER = """
            import org.kheperasim.api.*;

            public class BallSeeker extends Controller {
                protected void doWork() {
                    int[] image = vision().getImage();
                    int sum = 0, count = 0;
                    for (int i = 0; i < image.length; i++) {
                        if (image[i] > 120 && image[i] < 250) {
                            sum += i;
                            count++;
                        }
                    }
                    if (proximity(IrSensor.FRONT_LEFT) > 700 || proximity(IrSensor.FRONT_RIGHT) > 700) {
                        stopMotors();
                        print("at the ball");
                        killControl();
                    } else if (count == 0) {
                        setSpeeds(2, -2);                    // look around
                    } else {
                        int turn = (int) Math.round((sum / (double) count - 31.5) / 8);
                        setSpeeds(4 + turn, 4 - turn);       // a pixel right of the middle: turn right
                    }
                    sleepMillis(50);
                }
            }
            """;

    @BeforeAll
    static void compileAndWriteAWorld() throws Exception {
        Path src = Files.createDirectories(dir.resolve("src"));
        classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d",
                classes.toString(), "--release", "17", "-proc:none"));
        for (String[] c : new String[][] {{"Starter", STARTER}, {"Turner", TURNER}, {"BallSeeker", BALL_SEEKER}}) {
            Path file = src.resolve(c[0] + ".java");
            Files.writeString(file, c[1]);
            args.add(file.toString());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])));
        // The robot starts at the original's spot, (263, 263) px facing east; a ball 30 degrees to its
        // right, 100 px (244 mm) away; a lamp far behind.
        world = dir.resolve("course.map");
        Files.write(world, WsuWorldWriter.world(List.of(ball(5, 345, 308), light(6, 40, 40))));
    }

    private static Simulation.Builder run(String controller, double seconds, List<String> console) {
        return Simulation.builder().arena(world.toString()).classpath(List.of(classes)).controller(controller)
                .seed(7).seconds(seconds).console((ConsoleLine l) -> console.add(l.text()));
    }

    @Test
    void speedsSetInAnOverriddenSimStartMoveTheRobotAtTimeZero() {
        List<RobotView> seen = new CopyOnWriteArrayList<>();
        run("Starter", 2, new ArrayList<>()).listener(s -> seen.add(s.robots().get(0)), 10).run();
        RobotView at20ms = seen.get(2);
        assertEquals(5, at20ms.speedLeft(), "moving 20 ms into the run, before the first doWork(): " + at20ms);
        assertEquals(5, at20ms.speedRight());
        RobotView at1s = seen.get(100);
        assertEquals(-5, at1s.speedLeft(), "doWork's -5 on the left: " + at1s);
        assertEquals(5, at1s.speedRight(), "the right wheel kept simStart's 5 when doWork asked 70");
    }

    @Test
    void legacySpeedsDriveAsFastAsTheOriginalDrew() {
        List<RobotView> seen = new CopyOnWriteArrayList<>();
        run("Starter", 0.5, new ArrayList<>()).settings(Settings.defaults().with("wsu.speedUnits", "legacy"))
                .listener(s -> seen.add(s.robots().get(0)), 10).run();
        RobotView at20ms = seen.get(2);
        assertEquals(19, at20ms.speedLeft(), "5 WSU units are 19 Khepera units (3.78 each): " + at20ms);
        assertEquals(19, at20ms.speedRight());
        RobotView at400ms = seen.get(40);
        RobotView at200ms = seen.get(20);
        double mmPerS = (at400ms.x() - at200ms.x()) / 0.2;
        assertEquals(151, mmPerS, 8, "about 151 mm/s, the original's 980 counts a second at speed 5");
    }

    private static double[] numbers(List<String> console, String head) {
        String line = console.stream().filter(l -> l.startsWith(head + " ")).findFirst().orElseThrow();
        String[] t = line.split(" ");
        return new double[] {Double.parseDouble(t[1]), Double.parseDouble(t[2]), Double.parseDouble(t[3])};
    }

    @Test
    void aCountTunedTurnTurnsAsItsAuthorsSawWithLegacyUnitsAndThePoseIsInTheForksUnits() {
        List<String> console = new CopyOnWriteArrayList<>();
        RunResult legacy = run("Turner", 10, console)
                .settings(Settings.defaults().with("wsu.positionUnits", "legacy")).run();
        assertEquals(-45, legacy.first().headingDeg(), 5, "45 degrees to the right: " + legacy.first());
        double[] start = numbers(console, "start");
        assertEquals(263, start[0], 0, "x: the original's start spot, panel pixels");
        assertEquals(263, start[1], 0, "y: panel pixels down from the top");
        assertEquals(0, start[2], 1e-6, "facing east");
        double[] end = numbers(console, "end");
        assertEquals(Math.toRadians(-legacy.first().headingDeg()), end[2], 1e-3,
                "getRobotAngle: radians growing clockwise on the screen, 45 degrees right is +0.785");
        assertEquals(Math.round(legacy.first().x() / 2.4384), end[0], 0);
        assertEquals(Math.round((1219.2 - legacy.first().y()) / 2.4384), end[1], 0);

        RunResult pulses = run("Turner", 10, new ArrayList<>()).run();
        assertEquals(-23.3, pulses.first().headingDeg(), 3, "in encoder pulses the helper turns about half as far");
    }

    @Test
    void aControllerSteeringByTheVisionTurretReachesTheBall() {
        List<String> console = new CopyOnWriteArrayList<>();
        RunResult r = run("BallSeeker", 60, console).run();
        double ballX = (345 + 4.5) * 2.4384;
        double ballY = 1219.2 - (308 + 4.5) * 2.4384;
        double d = Math.hypot(r.first().x() - ballX, r.first().y() - ballY);
        assertTrue(console.contains("at the ball"), "it got there: " + console + " " + r.first());
        assertTrue(d < 27.5 + 11 + 15, "the ball is just ahead of it: " + d + " mm, " + r.first());
    }
}
