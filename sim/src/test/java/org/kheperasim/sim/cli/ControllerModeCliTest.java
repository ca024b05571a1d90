package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code run} and {@code bench} say where the controller runs, as the trace header records it. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ControllerModeCliTest {
    private String out;

    private int main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            return Main.commandLine().execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
        }
    }

    @Test
    void runSaysAStepControllerRunsOnBoardAndAThreadStyleOneTethered(@TempDir Path dir) throws Exception {
        Path trace = dir.resolve("step.trace");
        assertEquals(0, main("run", "--arena", "lab", "--controller", "StepBraitenberg", "--seconds", "2", "--seed", "1",
                "--trace", trace.toString()));
        assertTrue(out.lines().anyMatch(l -> l.startsWith("mode onboard-steps: the controller runs on the robot's own processor")), out);
        assertTrue(Files.readAllLines(trace).contains("# mode onboard-steps"), "the trace header agrees");

        assertEquals(0, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "2", "--seed", "1"));
        assertTrue(out.lines().anyMatch(l -> l.startsWith("mode tethered: the controller runs on the host")), out);

        assertEquals(0, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "2", "--seed", "1",
                "--set", "controller.mode=onboard"));
        assertTrue(out.lines().anyMatch(l -> l.startsWith("mode onboard: ")), out);
    }

    @Test
    void benchSaysTheModeAndTakesSettings() {
        assertEquals(0, main("bench", "--controller", "StepBraitenberg", "--seconds", "1", "--runs", "1", "--warm-up", "0",
                "--set", "controller.mode=tethered"));
        assertTrue(out.lines().anyMatch(l -> l.startsWith("mode tethered: ") && l.endsWith("settings controller.mode=tethered")), out);
    }
}
