package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * Controllers written for the WSU Khepera Simulator ({@code extends RobotController}, default
 * package) compiled from source and run by the simulator as they are: on the simulated clock,
 * deterministically, with a controller's exception reported and the run kept alive.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuControllerSimTest {
    @TempDir
    static Path classes;

    private static final Map<String, String> SOURCES = Map.of(
            "WsuAvoider", """
            import edu.wsu.KheperaSimulator.RobotController;

            public class WsuAvoider extends RobotController {
                public WsuAvoider() { }

                public void doWork() throws Exception {
                    if (getDistanceValue(1) > 400 || getDistanceValue(2) > 400 || getDistanceValue(3) > 400) {
                        setMotorSpeeds(3, -3);
                    } else if (getDistanceValue(4) > 400) {
                        setMotorSpeeds(-3, 3);
                    } else {
                        setMotorSpeeds(5, 5);
                    }
                    sleep(50);
                }

                public void close() throws Exception { setMotorSpeeds(0, 0); }
            }
            """,
            "WsuOdometer", """
            import edu.wsu.KheperaSimulator.RobotController;

            /** Busy-waits on its wheel counter, as students did, then stops itself. */
            public class WsuOdometer extends RobotController {
                public WsuOdometer() { }

                public void doWork() throws Exception {
                    long start = getLeftWheelPosition();
                    setMotorSpeeds(5, 5);
                    while (getLeftWheelPosition() - start < 1000) {
                        sleep(1);
                    }
                    setMotorSpeeds(0, 0);
                    setFinished(true);
                }

                public void close() throws Exception { }
            }
            """,
            "WsuWindowed", """
            import edu.wsu.KheperaSimulator.RobotController;

            public class WsuWindowed extends RobotController {
                public WsuWindowed() { }

                public void doWork() throws Exception {
                    setMotorSpeeds(4, 4);
                    sleep(500);
                    new javax.swing.JFrame("debug").setVisible(true);
                }

                public void close() throws Exception { }
            }
            """,
            "WsuCrasher", """
            import edu.wsu.KheperaSimulator.*;

            public class WsuCrasher extends RobotController {
                private int steps;
                public WsuCrasher() { }

                public void doWork() throws Exception {
                    setMotorSpeeds(6, 6);
                    if (++steps == 50) {
                        throw new java.io.IOException("student bug");
                    }
                }

                public void close() throws Exception { }
            }
            """);

    @BeforeAll
    static void compile() throws IOException {
        Path src = Files.createDirectories(classes.resolve("src"));
        List<String> args = new ArrayList<>(List.of("-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "-d", classes.toString()));
        for (Map.Entry<String, String> e : SOURCES.entrySet()) {
            Path file = src.resolve(e.getKey() + ".java");
            Files.writeString(file, e.getValue());
            args.add(file.toString());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])),
                "WSU controllers compile against the simulator's classes");
    }

    private static RunResult run(String controller, double seconds, List<ConsoleLine> console) {
        return Simulation.builder().arena("lab").controller(controller).classpath(List.of(classes)).seed(7)
                .seconds(seconds).console(console::add).run();
    }

    @Test
    void aWsuAvoiderRoamsTheLabDeterministically() {
        RunResult first = run("WsuAvoider", 120, new ArrayList<>());
        RunResult second = run("WsuAvoider", 120, new ArrayList<>());
        assertEquals("WsuAvoider", first.controller());
        assertEquals(120, first.simulatedSeconds(), 1e-6);
        assertTrue(first.first().distanceMm() > 2000, "it drives: " + first.first());
        assertEquals(first.first(), second.first(), "the same seed gives the same run");
    }

    @Test
    void wheelPositionsAndSleepAreOnTheSimulatedClock() {
        RunResult r = run("WsuOdometer", 60, new ArrayList<>());
        assertEquals(ControllerStatus.FINISHED, r.first().status(), String.valueOf(r.first()));
        // 1000 pulses at 5 pulses per 10 ms: two simulated seconds, plus the serial link's delays.
        assertTrue(r.simulatedSeconds() > 1.9 && r.simulatedSeconds() < 2.5, "ended at " + r.simulatedSeconds() + " s");
        assertEquals(80, r.first().distanceMm(), 8, "1000 pulses of 0.08 mm");
    }

    @Test
    void aWsuControllersExceptionIsReportedAndTheRobotStopped() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        RunResult r = run("WsuCrasher", 60, console);
        assertEquals(ControllerStatus.FAILED, r.first().status());
        assertTrue(r.first().failure().contains("java.io.IOException: student bug"), r.first().failure());
        assertTrue(console.stream().anyMatch(l -> l.text().contains("WsuCrasher.doWork")), console.toString());
        assertEquals(1.0, r.simulatedSeconds(), 0.1, "50 steps of 20 ms, then the run ended");
    }

    @Test
    void aControllersOwnWindowInAHeadlessRunIsAClearMessageNotACrash() {
        List<ConsoleLine> console = Collections.synchronizedList(new ArrayList<>());
        // A controller that opens a window of its own runs only trusted (untrusted, it is refused at load).
        RunResult r = Simulation.builder().arena("lab").controller("WsuWindowed").classpath(List.of(classes)).seed(7)
                .seconds(10).console(console::add).trusted(true).run();
        assertEquals(ControllerStatus.FAILED, r.first().status(), console.toString());
        String text = console.toString();
        assertTrue(text.contains("opened a window, but this run has no display"), text);
        assertTrue(text.contains("only in the simulator's window"), text);
        assertTrue(text.contains("WsuWindowed.doWork"), "the student's line is shown: " + text);
        assertEquals(0.5, r.simulatedSeconds(), 0.05, "it drove until it opened the window, then the run ended");
    }
}
