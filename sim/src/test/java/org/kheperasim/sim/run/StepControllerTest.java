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
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;

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

    /** The pose, speed and counter columns of a trace's samples (the sensor columns show what was delivered by then). */
    private static String motion(StringWriter trace) {
        return String.join("\n", trace.toString().lines().filter(l -> !l.startsWith("#"))
                .map(l -> String.join(" ", java.util.Arrays.asList(l.split(" ")).subList(0, 10))).toList());
    }

    @Test
    void aTetheredStepControllerDrivesExactlyAsTheSameLogicInAThreadDoes() {
        StringWriter thread = new StringWriter();
        StringWriter step = new StringWriter();
        Simulation.builder().arena("lab").controller("Braitenberg").seed(9).seconds(120).trace(thread).run();
        RunResult r = Simulation.builder().arena("lab").controller("StepBraitenberg").seed(9).seconds(120)
                .settings(org.kheperasim.sim.engine.model.Settings.defaults().with("controller.mode", "tethered")).trace(step)
                .run();
        // The same reads and commands at the same times through the link: the same path, to the last digit. (A
        // step runs whole inside its tick, so a reply its late calls bring in shows in that tick's sample, where
        // the thread's shows one tick later: the sensor columns may differ at such a tick, the path never.)
        assertEquals(motion(thread), motion(step), "Braitenberg's doWork() + sleepMillis(100) and StepBraitenberg's step()"
                + " every 100 ms, both through the serial link, drive the same path");
        assertTrue(r.first().distanceMm() > 2000, r.first().toString());
        assertEquals(ControllerStatus.STOPPED, r.first().status());
    }

    @Test
    void anOnBoardStepControllersCommandsActInTheSameStep() {
        List<long[]> speeds = new CopyOnWriteArrayList<>();
        for (String mode : List.of("onboard", "tethered")) {
            long[] first = {-1};
            Simulation.builder().arena("lab").controller("StepBraitenberg").seed(9).seconds(1)
                    .settings(org.kheperasim.sim.engine.model.Settings.defaults().with("controller.mode", mode))
                    .listener(s -> {
                        if (first[0] < 0 && s.robots().get(0).speedLeft() != 0) {
                            first[0] = s.timeNanos();
                        }
                    }, 1).run();
            speeds.add(first);
        }
        // On the robot, the first step's speeds (at 0) drive the robot from that very tick; through the link at
        // 38400 baud, only once the command's characters and the robot's turnaround have passed.
        assertEquals(0, speeds.get(0)[0], "on-board: the wheels turn from the tick of the step that set them");
        assertTrue(speeds.get(1)[0] >= 1_000_000, "tethered: the wheels turn after the wire time, at " + speeds.get(1)[0]);
    }

    @Test
    void aStepThatThrowsFailsTheControllerAtTheStudentsLine() {
        RunResult r = run("org.kheperasim.testcontrollers.StepThrower", 10, HostOptions.defaults());
        assertEquals(ControllerStatus.FAILED, r.first().status(), console.toString());
        // Ten steps, 100 ms apart: on the robot (on-board, a step controller's default) a step is one instant.
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
                    "-Xmx128m", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), org.kheperasim.sim.cli.Main.class.getName(), "run",
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
