package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.host.ConsoleLine;

import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * Step-style controllers: stepped inline once per period, with the same sensors, motors and link
 * timing as thread-style ones; their faults named; mixed with thread-style robots deterministically.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class StepControllerTest {
    private final List<String> console = new CopyOnWriteArrayList<>();

    private RunResult run(String controller, double seconds, HostOptions options) {
        return Simulation.builder().arena("lab").controller(controller).seed(9).seconds(seconds).hostOptions(options)
                .console((ConsoleLine l) -> console.add(l.text())).run();
    }

    private static String body(StringWriter trace) {
        return String.join("\n", trace.toString().lines().filter(l -> !l.startsWith("#")).toList());
    }

    @Test
    void aStepControllerDrivesExactlyAsTheSameLogicInAThreadDoes() {
        StringWriter thread = new StringWriter();
        StringWriter step = new StringWriter();
        Simulation.builder().arena("lab").controller("Braitenberg").seed(9).seconds(120).trace(thread).run();
        RunResult r = Simulation.builder().arena("lab").controller("StepBraitenberg").seed(9).seconds(120).trace(step).run();
        assertEquals(body(thread), body(step), "Braitenberg's doWork() + sleepMillis(100) and StepBraitenberg's step()"
                + " every 100 ms give the same samples, to the last digit");
        assertTrue(r.first().distanceMm() > 2000, r.first().toString());
        assertEquals(ControllerStatus.STOPPED, r.first().status());
    }

    @Test
    void aStepThatThrowsFailsTheControllerAtTheStudentsLine() {
        RunResult r = run("org.kheperasim.testcontrollers.StepThrower", 10, HostOptions.defaults());
        assertEquals(ControllerStatus.FAILED, r.first().status(), console.toString());
        // Ten steps, each one period (100 ms) after the previous step's last call (20 us each).
        assertTrue(console.contains("tenth step at 60900"), console.toString());
        assertTrue(console.stream().anyMatch(l -> l.contains("ArithmeticException") && l.contains("StepThrower.step(StepThrower.java:")),
                console.toString());
        assertTrue(r.simulatedSeconds() < 1.0, "the run ended with its only controller: " + r.simulatedSeconds());
    }

    @Test
    void aStepThatSleepsBreaksTheContractWithAClearMessage() {
        RunResult r = run("org.kheperasim.testcontrollers.StepSleeper", 5, HostOptions.defaults());
        assertEquals(ControllerStatus.FAILED, r.first().status(), console.toString());
        assertTrue(console.stream().anyMatch(l -> l.contains("slept in step(): a step must return instead")), console.toString());
    }

    @Test
    void aStepThatNeverReturnsIsStoppedAndNamed() {
        RunResult r = run("org.kheperasim.testcontrollers.StepLooper", 5,
                HostOptions.defaults().withHangTimeout(TimeUnit.SECONDS.toNanos(1)));
        assertEquals(ControllerStatus.HUNG, r.first().status(), console.toString());
        assertTrue(console.stream().anyMatch(l -> l.contains("step() did not return")), console.toString());
        assertTrue(r.simulatedSeconds() >= 0.4 && r.simulatedSeconds() <= 0.5, "it hung in its fifth step, at 0.4 s, and the run"
                + " ended soon after: " + r.simulatedSeconds());
    }

    @Test
    void stepAndThreadRobotsTogetherRepeatExactlyWithJitter() {
        String[] traces = new String[2];
        for (int k = 0; k < 2; k++) {
            StringWriter t = new StringWriter();
            Simulation.Builder b = Simulation.builder().arena(MultiRobotTest.crowd(10)).controller("StepBraitenberg")
                    .seed(4).seconds(20).trace(t).hostOptions(HostOptions.defaults().withJitter(k * 300));
            b.robot(0, "Braitenberg", null).robot(5, "WallFollower", null);
            RunResult r = b.run();
            assertEquals(10, r.robots().size());
            traces[k] = t.toString();
        }
        assertEquals(traces[0], traces[1], "thread-style and step-style robots in one run repeat exactly");
    }

    /** In a JVM of its own with a small heap: a step controller that keeps what it allocates is stopped before the heap runs out. */
    @Test
    void aStepControllerThatFillsTheHeapIsStoppedBeforeItRunsOut() throws Exception {
        java.nio.file.Path out = java.nio.file.Files.createTempFile("stephog", ".txt");
        try {
            Process p = new ProcessBuilder(java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-Xmx128m", "-cp", System.getProperty("java.class.path"), org.kheperasim.sim.cli.Main.class.getName(), "run",
                    "--arena", "lab", "--controller", "org.kheperasim.testcontrollers.StepHog", "--seconds", "60", "--seed", "1")
                    .redirectErrorStream(true).redirectOutput(out.toFile()).start();
            assertTrue(p.waitFor(90, TimeUnit.SECONDS), "the run ends");
            String text = java.nio.file.Files.readString(out);
            assertEquals(1, p.exitValue(), text);
            assertTrue(text.contains("ERROR StepHog: controller StepHog allocated without bound ("), text);
            assertTrue(text.contains("controller exceeded_memory"), "the result line is printed: " + text);
            assertTrue(!text.contains("the Java heap ran out"), "stopped before the heap ran out: " + text);
        } finally {
            java.nio.file.Files.deleteIfExists(out);
        }
    }
}
