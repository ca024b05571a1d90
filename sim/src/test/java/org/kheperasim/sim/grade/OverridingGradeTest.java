package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code grade} of students whose controllers override their {@code Thread}'s methods or the
 * Appendix's {@code killControl()} to spin or throw: each run ends as the same controller's without
 * the override does, with its status and its points (before the fix a spinning {@code killControl()}
 * ran on the run's own thread: the run took the whole wall limit and was graded hung).
 */
class OverridingGradeTest {
    @TempDir
    Path dir;

    /** The Appendix's shape; {@code %s}: the body of killControl(), what each step ends with, the overrides. */
    private static final String ROBOT = """
            import org.kheperasim.api.*;

            public class Robot extends Thread {
                private final CurrentRobotState data;
                private volatile boolean active = true;
                static volatile long n;

                public Robot(CurrentRobotState data, MessagePasser mp) {
                    this.data = data;
                }

                public void killControl() {
                    %s
                }

                @Override
                public void run() {
                    Sensor[] s = data.getSensorValues();
                    Motor m = data.getMotorState();
                    long steps = 0;
                    while (active) {
                        m.setMotorSpeeds(Math.max(s[2].getDistValue(), s[3].getDistValue()) > 500 ? -3 : 5, 4);
                        try {
                            Thread.sleep(100);
                        } catch (InterruptedException e) {
                            // go on
                        }
                        steps++;
                        %s
                    }
                }
                %s
            }
            """;

    private static final String SPIN = "while (n >= 0) { n++; }";
    private static final String QUIT = "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }";

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void overridesChangeNoRunsOutcome() throws IOException {
        Path subs = dir.resolve("submissions");
        student(subs, "plain", "active = false;", "", "");
        student(subs, "killspins", "active = false; " + SPIN, "", "");
        student(subs, "killthrows", "throw new IllegalStateException(\"not now\");", "", "");
        student(subs, "startspins", "active = false;", "", "@Override public void start() { " + SPIN + " }");
        student(subs, "statethrows", "active = false;", "", "@Override public State getState() { throw new IllegalStateException(); }");
        student(subs, "quits", "active = false;", QUIT, "");
        student(subs, "quitsnohandler", "active = false;", QUIT,
                "@Override public UncaughtExceptionHandler getUncaughtExceptionHandler() { " + SPIN + " return null; }");
        Path out = dir.resolve("report");
        String printed = grade("--submissions", subs.toString(), "--arenas", "maze", "--seeds", "1", "--seconds", "20",
                "--jobs", "2", "--out", out.toString(), "--hang-timeout", "5", "--wall-limit", "120", "--no-sandbox");

        Map<String, RunRecord> runs = new TreeMap<>();
        for (RunRecord r : ReportFiles.readCsv(out.resolve("results.csv"))) {
            runs.put(r.student(), r);
        }
        RunRecord plain = runs.get("plain");
        RunRecord quits = runs.get("quits");
        assertEquals(RunStatus.OK, plain.status(), printed);
        assertEquals(RunStatus.THREW, quits.status(), printed);
        for (String s : List.of("killspins", "killthrows", "startspins", "statethrows")) {
            assertSame(plain, runs.get(s), printed);
        }
        assertSame(quits, runs.get("quitsnohandler"), printed);
        assertTrue(runs.get("quitsnohandler").detail().startsWith("java.lang.IllegalStateException: gave up"),
                runs.get("quitsnohandler").detail());
    }

    private static void assertSame(RunRecord expected, RunRecord actual, String printed) {
        String why = actual.student() + " is graded as " + expected.student() + ": " + actual + "\n" + printed;
        assertEquals(expected.status(), actual.status(), why);
        assertEquals(expected.points(), actual.points(), 0, why);
        assertEquals(expected.simulatedSeconds(), actual.simulatedSeconds(), 0, why);
    }

    private static void student(Path subs, String name, String kill, String step, String overrides) throws IOException {
        Path folder = Files.createDirectories(subs.resolve(name));
        Files.writeString(folder.resolve("Robot.java"), ROBOT.formatted(kill, step, overrides));
    }

    private static String grade(String... args) {
        String[] full = new String[args.length + 1];
        full[0] = "grade";
        System.arraycopy(args, 0, full, 1, args.length);
        Cli.Printed p = Cli.main(full);
        assertEquals(0, p.code(), p.out() + p.err());
        return p.out();
    }
}
