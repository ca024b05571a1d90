package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * What public WSU course code does, in small controllers of this project's own written in the same
 * patterns, run untrusted: the observer pattern with {@code java.awt} geometry and colour values and
 * a {@code Calendar} (on the simulated clock), a {@code sleep} in the constructor, and a course's own
 * base class placed in the package {@code edu.wsu.KheperaSimulator} (as a fork of the original did),
 * which loads from the classpath but gets no package-private access to the simulator's classes.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuCourseCodeTest {
    @TempDir
    static Path classes;

    private static final Map<String, String> SOURCES = Map.of(
            "CourseObserver.java", """
            import edu.wsu.KheperaSimulator.RobotController;
            import java.awt.Color;
            import java.awt.Point;
            import java.awt.Rectangle;
            import java.awt.geom.Line2D;
            import java.awt.geom.Point2D;
            import java.util.Calendar;
            import java.util.Observable;
            import java.util.Observer;

            public class CourseObserver extends RobotController implements Observer {
                static class Wheels extends Observable {
                    void tick(long left) { setChanged(); notifyObservers(Long.valueOf(left)); }
                }
                private final Wheels wheels = new Wheels();
                private final Rectangle box = new Rectangle(0, 0, 100, 100);
                private Point2D last = new Point2D.Double(0, 0);
                private int updates;

                public CourseObserver() {
                    wheels.addObserver(this);
                    sleep(300);
                }

                public void update(Observable o, Object arg) {
                    updates++;
                    Point p = new Point((int) ((Long) arg).longValue() % 100, 5);
                    if (box.contains(p) && new Line2D.Double(0, 0, 10, 0).ptSegDist(last) >= 0) {
                        last = new Point2D.Float(p.x, p.y);
                    }
                }

                public void doWork() throws Exception {
                    if (updates == 0) {
                        Calendar c = Calendar.getInstance();
                        System.out.println("first at " + System.currentTimeMillis() + " calendar " + c.getTimeInMillis()
                                + " colour " + Color.ORANGE.darker().getRed());
                    }
                    setMotorSpeeds(3, 3);
                    wheels.tick(getLeftWheelPosition());
                    if (updates == 20) {
                        setFinished(true);
                    }
                }

                public void close() throws Exception { setMotorSpeeds(0, 0); }
            }
            """,
            "edu/wsu/KheperaSimulator/CourseVehicleBase.java", """
            package edu.wsu.KheperaSimulator;

            /** A course's own base class in the simulator's package, as a fork of the original had. */
            public abstract class CourseVehicleBase extends RobotController {
                protected void drive(int left, int right) { setMotorSpeeds(left, right); }
                public void close() throws Exception { setMotorSpeeds(0, 0); }
            }
            """,
            "CourseVehicle.java", """
            import edu.wsu.KheperaSimulator.CourseVehicleBase;

            public class CourseVehicle extends CourseVehicleBase {
                public CourseVehicle() { }
                public void doWork() throws Exception {
                    drive(4, 4);
                    sleep(100);
                }
            }
            """,
            "edu/wsu/KheperaSimulator/CoursePeeker.java", """
            package edu.wsu.KheperaSimulator;

            /** Tries the simulator's package-private members from a class of the same package name. */
            public class CoursePeeker extends RobotController {
                public CoursePeeker() { }
                public void doWork() throws Exception {
                    robot().setMotorSpeeds(9, 9);
                }
                public void close() throws Exception { }
            }
            """);

    @BeforeAll
    static void compile() throws IOException {
        Path src = Files.createDirectories(classes.resolve("src"));
        List<String> args = new ArrayList<>(List.of("-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "-d", classes.toString(), "-proc:none"));
        for (Map.Entry<String, String> e : SOURCES.entrySet()) {
            Path file = src.resolve(e.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, e.getValue());
            args.add(file.toString());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])),
                "the course-style controllers compile against the simulator's classes");
    }

    private static RunResult run(String controller, double seconds, List<ConsoleLine> console) {
        return Simulation.builder().arena("lab").controller(controller).classpath(List.of(classes)).seed(3)
                .seconds(seconds).console(console::add).run();
    }

    @Test
    void observersGeometryColourAndACalendarRunUntrustedOnTheSimulatedClock() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        RunResult r = run("CourseObserver", 30, console);
        assertEquals(ControllerStatus.FINISHED, r.first().status(), r.first() + " " + console);
        String first = console.stream().map(ConsoleLine::text).filter(t -> t.startsWith("first at ")).findFirst()
                .orElseThrow(() -> new AssertionError("no first line: " + console));
        String[] words = first.split(" ");
        long millis = Long.parseLong(words[2]);
        long calendar = Long.parseLong(words[4]);
        assertEquals(millis, calendar, 0, "Calendar.getInstance() reads the simulated clock: " + first);
        assertTrue(calendar < 1_000_000_000_000L + 10_000_000_000L, "the simulated clock starts in 2001: " + first);
    }

    @Test
    void aSleepInTheConstructorIsAPlainSleepOfSimulatedTime() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        RunResult r = run("CourseObserver", 30, console);
        ConsoleLine first = console.stream().filter(l -> l.text().startsWith("first at ")).findFirst()
                .orElseThrow(() -> new AssertionError("the controller ran: " + r.first() + " " + console));
        // The constructor slept 300 ms of robot time: the first doWork() comes after it.
        assertTrue(first.timeNanos() >= 300_000_000L && first.timeNanos() < 400_000_000L,
                "first doWork at " + first.timeNanos() / 1e6 + " ms");
    }

    @Test
    void aCoursesOwnClassInTheSimulatorsPackageLoadsFromItsClasspath() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        RunResult r = run("CourseVehicle", 5, console);
        assertFalse(r.first().status().failed(), r.first() + " " + console);
        assertTrue(r.first().distanceMm() > 50, "it drives through its own base class: " + r.first());
    }

    @Test
    void suchAClassGetsNoPackagePrivateAccessToTheSimulatorsClasses() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        RunResult r = run("edu.wsu.KheperaSimulator.CoursePeeker", 5, console);
        assertEquals(ControllerStatus.FAILED, r.first().status(), r.first() + " " + console);
        assertTrue(r.first().failure().contains("IllegalAccessError"), r.first().failure());
        assertEquals(0, r.first().distanceMm(), 1e-9, "it never reached the motors");
    }

    @Test
    void aNameBothDefineIsTheSimulatorsAndTheMessageSaysSo() throws IOException {
        Path both = Files.createDirectories(classes.resolve("both/edu/wsu/KheperaSimulator"));
        // A course's copy of the original's classes: its RobotController is not the one used.
        Files.copy(classes.resolve("edu/wsu/KheperaSimulator/CoursePeeker.class"), both.resolve("RobotController.class"));
        ControllerCatalog catalog = new ControllerCatalog(List.of(classes.resolve("both")));
        ControllerException e = assertThrows(ControllerException.class, () -> catalog.load("edu.wsu.KheperaSimulator.RobotController"));
        assertTrue(e.getMessage().contains("edu.wsu.KheperaSimulator.RobotController is defined by both the simulator and the"
                + " classpath: the simulator's own class is used"), e.getMessage());
    }
}
