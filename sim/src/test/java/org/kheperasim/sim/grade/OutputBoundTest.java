package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.cli.Main;

/**
 * A controller that prints 1 KB to System.err every simulated millisecond (20 MB in 20 s; the table
 * of issue 28 measured 200 MB in 12 s for 10 KB lines) gets about 1 MiB of console, in {@code run}
 * and under {@code grade}; the console and the report say how much was dropped.
 */
class OutputBoundTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRunPrintsAboutOneMebibyteAndSaysWhatItDropped() throws IOException {
        Path classes = compiledChatter();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        int code;
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            code = Main.commandLine().execute("run", "--arena", "maze", "--classpath", classes.toString(), "--controller",
                    "Chatter", "--seconds", "20", "--seed", "1");
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(0, code, text.substring(StrictMath.max(0, text.length() - 2000)));
        long printed = out.size() + err.size();
        assertTrue(printed > 1_000_000 && printed < 1_300_000, printed + " bytes printed; the limit is 1 MiB of line text");
        assertTrue(text.matches("(?s).*khepera-sim: printed 20 MB of controller output; kept the first 1 MB \\(the run's"
                + " limit\\), dropped \\d{5} lines.*"), text.substring(text.length() - 300));
    }

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theReportSaysWhatARunDropped() throws IOException {
        Path subs = dir.resolve("subs");
        Hostile.chatterbox(subs.resolve("chad"));
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("maze"), 1, 1, dir.resolve("out"),
                GradePlan.Shard.ALL, 256, 120, 5, 20.0, false, new PrintStream(OutputStream.nullOutputStream()), false, box, false));
        RunRecord chad = report.runs().get(0);
        assertEquals(RunStatus.OK, chad.status(), chad.toString());
        assertTrue(chad.detail().endsWith(" | printed 20 MB; kept the first 1 MB"), chad.detail());
        assertTrue(Files.readString(dir.resolve("out").resolve("report.txt")).contains("Output cut at the run's limit:\n"
                + "  chad, seed 1: printed 20 MB; kept the first 1 MB\n"), "report.txt says it");
    }

    /**
     * A controller that prints 100 lines every simulated millisecond (100,000 a simulated second, 30 million
     * lines in 300 s) is graded on what its robot did: ok, with the score of the same controller printing
     * nothing, within a wall-clock limit of 20 s. Each dropped line cost about one microsecond of encoding,
     * decoding and copying in the run's JVM idle, three at load 22 (173 s for 600 s of this controller then,
     * 9 s since): every run was {@code hung} at the wall-clock limit, 0 points.
     */
    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aHeavyPrinterIsGradedOnWhatItsRobotDid() throws IOException {
        Path subs = dir.resolve("subs");
        printer(subs.resolve("pat"), true);
        printer(subs.resolve("quinn"), false);
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("lab"), 1, 1, dir.resolve("out"),
                GradePlan.Shard.ALL, 128, 20, 5, 300.0, false, new PrintStream(OutputStream.nullOutputStream()), false, box,
                false));
        RunRecord pat = report.runs().get(0);
        RunRecord quinn = report.runs().get(1);
        assertEquals(RunStatus.OK, quinn.status(), quinn.toString());
        assertEquals(RunStatus.OK, pat.status(), pat.toString());
        assertEquals(quinn.points(), pat.points(), "printing costs no simulated time: the same robot, the same score");
        assertEquals(300, pat.simulatedSeconds(), 1e-9);
        assertTrue(pat.detail().matches(".* \\| printed \\d{3} MB; kept the first 1 MB"), pat.detail());
    }

    /**
     * A fault's message is bounded like output: a controller that throws an exception with a 5 MB message
     * gets a few KB of console and of {@code run --json}'s failure, with its own line kept.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aFaultMessageIsBoundedLikeOutput() throws IOException {
        Path src = Files.createDirectories(dir.resolve("thrower"));
        Files.writeString(src.resolve("Thrower.java"), """
                import org.kheperasim.api.*;

                public class Thrower extends Controller {
                    @Override
                    protected void doWork() {
                        throw new IllegalStateException("x".repeat(5_000_000));
                    }
                }
                """);
        Path classes = Files.createDirectories(dir.resolve("thrower-classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), src.resolve("Thrower.java").toString()));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            Main.commandLine().execute("run", "--arena", "lab", "--classpath", classes.toString(), "--controller", "Thrower",
                    "--seconds", "2", "--seed", "1", "--json");
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertTrue(err.size() < 40_000, err.size() + " bytes of standard error");
        assertTrue(text.contains("at Thrower.doWork(Thrower.java:6)"), text.substring(0, 300));
        assertTrue(out.size() < 40_000, out.size() + " bytes of JSON");
    }

    /** A controller that drives and, when {@code loud}, prints 100 lines each simulated millisecond. */
    private static void printer(Path folder, boolean loud) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Printer.java"), """
                import org.kheperasim.api.*;

                public class Printer extends Controller {
                    private long n;

                    @Override
                    protected void doWork() {
                        setSpeeds(proximity(IrSensor.FRONT_LEFT) > 500 ? -3 : 5, 5);
                        for (int i = 0; i < 100; i++) {
                            if (%s) {
                                System.out.println("the robot takes a step");
                            }
                            n++;
                        }
                        sleepMillis(1);
                    }
                }
                """.formatted(loud));
    }

    private Path compiledChatter() throws IOException {
        Path src = dir.resolve("src");
        Hostile.chatterbox(src);
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), src.resolve("Chatter.java").toString()));
        return classes;
    }
}
