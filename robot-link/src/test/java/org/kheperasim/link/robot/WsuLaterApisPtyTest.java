package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * What later WSU course code relies on, run on the fake robot over a socat pty pair: {@code simStart()}
 * overridden to set speeds at time 0, KSuite 1.1.2's K213 vision turret read through the turret's own
 * commands, the original's wheel counts ({@code wsu.positionUnits=legacy}) for a count-tuned turn, and
 * the later fork's pose API answered from odometry with a note.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy.
 */
@Tag("timing")
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuLaterApisPtyTest {
    @TempDir
    Path dir;

    private final List<String> console = Collections.synchronizedList(new ArrayList<>());
    private final Consumer<String> out = console::add;

    /** As 2012 course controllers start: speeds set in simStart(); doWork() asks for one out of range. */
    private static final String STARTER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Starter extends RobotController {
                private int steps;
                public Starter() { }

                @Override
                public void simStart() {
                    super.simStart();
                    this.setMotorSpeeds(5, 5);
                }

                public void doWork() throws Exception {
                    sleep(200);
                    setMotorSpeeds(-5, 70);                 // 70 is ignored: the right wheel keeps 5
                    if (++steps == 3) {
                        setFinished(true);
                    }
                }

                public void close() throws Exception { }
            }
            """;

    /** Reads the turret and tells what it saw through the speeds it sets (the test cannot see its fields). */
    private static final String LOOKER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Looker extends RobotController {
                private int rounds;

                public Looker() { }

                // Ten rounds of 100 ms (wall time on the robot): a busy test machine may hold the poll loop
                // that sends the speeds back for a while; a single round was not always enough.
                public void doWork() throws Exception {
                    float[] image = readLvtImage();
                    int max = (int) getPixelMaxIntensity();
                    int min = (int) getPixelMinIntensity();
                    setMotorSpeeds(image.length == 64 ? max / 32 : 0, min / 32 + 1);
                    sleep(100);
                    if (++rounds >= 10) {
                        setFinished(true);
                    }
                }

                public void close() throws Exception { }
            }
            """;

    /** A new controller pointing at the turret's brightest and darkest pixels (the turret's own O and P). */
    private static final String POINTER = """
            import org.kheperasim.api.*;

            public class Pointer extends Controller {
                private int rounds;

                protected void doWork() {
                    int brightest = vision().getBrightestPixel();
                    int darkest = vision().getDarkestPixel();
                    setSpeeds(brightest - 32, darkest - 10);
                    sleepMillis(100);
                    if (++rounds >= 10) {
                        killControl();
                    }
                }
            }
            """;

    /** A helper of the kind course code has: turn on the spot until the counter has moved 3 counts a degree. */
    private static final String TURNER = """
            import edu.wsu.KheperaSimulator.RobotController;

            public class Turner extends RobotController {
                public Turner() { }

                public void doWork() throws Exception {
                    long start = getLeftWheelPosition();
                    setMotorSpeeds(2, -2);
                    while (Math.abs(getLeftWheelPosition() - start) / 3 < 45) {
                        sleep(1);
                    }
                    setMotorSpeeds(0, 0);
                    sleep(200);
                    float angle = getRobotAngle();
                    int x = getRobotXPosition();
                    // Equal speeds drive straight: the turn the test measures stays as it was.
                    setMotorSpeeds(Math.round(angle * 10), Math.round(angle * 10));
                    sleep(300);
                    setMotorSpeeds(x - 263 + 1, x - 263 + 1);
                    sleep(300);
                    setFinished(true);
                }

                public void close() throws Exception { }
            }
            """;

    private Class<?> compile(String name, String source) throws Exception {
        Path src = Files.createDirectories(dir.resolve("src"));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        Path file = src.resolve(name + ".java");
        Files.writeString(file, source);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "-d", classes.toString(), file.toString()));
        return new ControllerLoader(List.of(classes)).load(name);
    }

    private RobotRun.Result run(FakeRobotOnPty fake, Class<?> controller, RobotSettings settings) throws Exception {
        SerialLink link = SerialLink.open(SerialSettings.khepera(fake.hostPath(), 38400));
        // No fault is injected: a reply may take 1 s (150 ms timed out answered commands on a machine at load 30).
        try (Session s = new Session(link, LinkTiming.atBaud(38400), new Session.Options(1000, 3, 100, 2000))) {
            s.open();
            return new RobotRun(new RobotBackend(s, settings, out), controller, out).run(20_000);
        }
    }

    private static List<String> speeds(FakeKhepera robot) {
        return robot.received().stream().filter(l -> l.startsWith("D,")).toList();
    }

    @Test
    void speedsSetInSimStartAreTheFirstTheRobotHears() throws Exception {
        Class<?> starter = compile("Starter", STARTER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, starter, RobotSettings.defaults());
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            List<String> d = speeds(fake.robot());
            assertEquals("D,0,0", d.get(0), "robot-link's own stop before the controller starts: " + d);
            assertEquals("D,5,5", d.get(1), "simStart's speeds go out before the first doWork(): " + d);
            assertEquals("D,-5,5", d.get(2), "the right wheel kept simStart's 5 when doWork asked 70: " + d);
            assertEquals(1, d.stream().filter(l -> l.equals("D,5,5")).count(), "simStart ran once: " + d);
            assertEquals("D,0,0", fake.robot().lastReceived());
        }
    }

    @Test
    void legacySpeedsAreSentAsFastAsTheOriginalDrewThem() throws Exception {
        Class<?> starter = compile("Starter", STARTER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, starter, RobotSettings.defaults().withMaxSpeed(40)
                    .withOption("wsu.speedUnits", "legacy"));
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            List<String> d = speeds(fake.robot());
            assertEquals("D,19,19", d.get(1), "5 WSU units are 19 Khepera units (about 151 mm/s): " + d);
            assertEquals("D,-19,19", d.get(2), d.toString());
        }
    }

    @Test
    void theVisionTurretIsReadWithItsOwnCommands() throws Exception {
        Class<?> looker = compile("Looker", LOOKER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            fake.robot().vision().fill(20);
            fake.robot().vision().object(-5, 3, 255);   // a lamp a little to the right
            fake.robot().vision().object(10, 2, 0);     // something black to the left
            RobotRun.Result r = run(fake, looker, RobotSettings.defaults());
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            assertTrue(fake.robot().received().contains("T,2,N"), "the image: " + fake.robot().received());
            assertTrue(speeds(fake.robot()).contains("D,7,1"), "the greatest level 255 and the least 0: " + speeds(fake.robot()));
        }
        Class<?> pointer = compile("Pointer", POINTER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(Files.createDirectories(dir.resolve("pointer")), null)) {
            fake.robot().vision().fill(20);
            fake.robot().vision().object(-5, 3, 255);
            fake.robot().vision().object(10, 2, 0);
            int brightest = fake.robot().vision().brightest();
            int darkest = fake.robot().vision().darkest();
            assertTrue(brightest > 31 && darkest < 31, "the scene: bright on the right, dark on the left");
            RobotRun.Result r = run(fake, pointer, RobotSettings.defaults());
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            List<String> got = fake.robot().received();
            assertTrue(got.contains("T,2,O") && got.contains("T,2,P"), "the turret's own commands: " + got);
            assertTrue(speeds(fake.robot()).contains("D," + (brightest - 32) + "," + (darkest - 10)),
                    "the brightest and darkest pixels' indices: " + speeds(fake.robot()));
        }
    }

    @Test
    void aRobotWithoutTheTurretWarnsOnceAndGivesDarkImages() throws Exception {
        Class<?> looker = compile("Looker", LOOKER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            fake.robot().setVisionFitted(false);
            RobotRun.Result r = run(fake, looker, RobotSettings.defaults());
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            assertEquals(1, console.stream().filter(l -> l.contains("K213 vision turret fitted")).count(), "" + console);
            assertTrue(speeds(fake.robot()).contains("D,0,1"), "a dark image: 0 and 0: " + speeds(fake.robot()));
        }
    }

    private static double turnedDeg(FakeKhepera robot) {
        int[] p = robot.positions();
        return Math.toDegrees((p[1] - p[0]) / 2.0 * 0.08 / 26.5);
    }

    @Test
    void countTunedTurnsTurnAsTheirAuthorsSawWithLegacyUnitsAndThePoseComesFromOdometry() throws Exception {
        Class<?> turner = compile("Turner", TURNER);
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            RobotRun.Result r = run(fake, turner, RobotSettings.defaults().withOption("wsu.positionUnits", "legacy"));
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            double turned = turnedDeg(fake.robot());
            assertEquals(-45, turned, 5, "45 degrees to the right, as on the original");
            List<String> d = speeds(fake.robot());
            int turn = d.indexOf("D,2,-2");
            assertEquals("D,0,0", d.get(turn + 1), "it stopped after the turn: " + d);
            int tenths = Integer.parseInt(d.get(turn + 2).split(",")[1]);
            assertEquals(-turned / 180 * Math.PI * 10, tenths, 1.0, "getRobotAngle: clockwise radians, from odometry: " + d);
            assertEquals("D,1,1", d.get(turn + 3), "it turned on the spot: still at x 263 px: " + d);
            assertEquals(1, console.stream().filter(l -> l.contains("come from the wheels' odometry")).count(),
                    "the note, once: " + console);
        }
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(Files.createDirectories(dir.resolve("pulses")), null)) {
            RobotRun.Result r = run(fake, turner, RobotSettings.defaults());
            assertEquals(RobotRun.End.FINISHED, r.end(), r.detail());
            assertEquals(-23.3, turnedDeg(fake.robot()), 4, "in encoder pulses the same helper turns about half as far");
        }
    }
}
