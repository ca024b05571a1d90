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
        assertTrue(text.matches("(?s).*khepera-sim: dropped \\d{5} lines \\(\\d+ MB\\) of controller output over the run's"
                + " limit of 1049 KB.*"), text.substring(text.length() - 300));
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
        assertTrue(chad.detail().matches(".*\\| dropped \\d{5} lines \\(\\d+ MB\\) of controller output over the run's limit of"
                + " 1049 KB"), chad.detail());
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
