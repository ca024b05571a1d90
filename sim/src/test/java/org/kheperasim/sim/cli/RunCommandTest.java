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

/** The command line as a user runs it. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunCommandTest {
    private String out;
    private String err;

    private int main(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            return Main.commandLine().execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
    }

    @Test
    void runPrintsTheSeedAndOneLineOfResult() {
        assertEquals(0, main("run", "--arena", "maze", "--controller", "WallFollower", "--seconds", "30", "--seed", "4"));
        String[] lines = out.strip().split("\\R");
        assertEquals("seed 4", lines[0]);
        assertTrue(lines[lines.length - 1].startsWith("WallFollower in maze: 30.0 s simulated in "), out);
        assertTrue(lines[lines.length - 1].contains("controller stopped"), out);
    }

    @Test
    void jsonHasTheSummaryAndTheTraceHash(@TempDir Path dir) throws Exception {
        Path trace = dir.resolve("run.trace");
        assertEquals(0, main("run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "20", "--seed", "9",
                "--trace", trace.toString(), "--json"));
        String json = out.strip();
        assertTrue(json.startsWith("{") && json.endsWith("}") && json.lines().count() == 1, json);
        for (String key : new String[] {"\"seed\":9", "\"simulatedSeconds\":20", "\"wallSeconds\":", "\"finalPose\":{\"x\":",
            "\"distanceMm\":", "\"collisions\":", "\"visitedPercent\":", "\"traceSha256\":\"", "\"controllerStatus\":\"stopped\""}) {
            assertTrue(json.contains(key), key + " missing from " + json);
        }
        String sha = json.replaceAll(".*\"traceSha256\":\"([0-9a-f]{64})\".*", "$1");
        byte[] digest = java.security.MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(trace));
        assertEquals(java.util.HexFormat.of().formatHex(digest), sha, "the hash is the trace file's");
        assertTrue(err.contains("seed 9"), "with --json the seed goes to standard error: " + err);
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "the trace is written atomically: no temporary file is left");
        }
    }

    @Test
    void badInputExitsWithTwoAndSaysWhatToFix(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.arena");
        Files.writeString(bad, "khepera-arena 1\nname bad\nsize 1000 1000\nwal 0 0 10 10 5\n");
        assertEquals(2, main("run", "--arena", bad.toString(), "--controller", "WallFollower"));
        assertTrue(err.contains("bad.arena:4: "), err);
        assertEquals(2, main("run", "--arena", "lab", "--controller", "Nope"));
        assertTrue(err.contains("no controller named 'Nope'"), err);
        assertEquals(2, main("run", "--arena", "lab", "--controller", "Braitenberg", "--set", "prox.9.gain=2"));
        assertTrue(err.contains("unknown setting 'prox.9.gain'"), err);
    }

    @Test
    void aFailingControllerExitsWithOne() {
        assertEquals(1, main("run", "--arena", "lab", "--controller", "org.kheperasim.testcontrollers.Thrower", "--seconds", "5"));
        assertTrue(err.contains("ArithmeticException"), err);
    }

    private static Path threeRobots(Path dir) throws Exception {
        Path arena = dir.resolve("three.arena");
        Files.writeString(arena, "khepera-arena 1\nname three\nsize 1219.2 1219.2\nrobot 300 300 0\nrobot 900 300 90\n"
                + "robot 600 900 180\n");
        return arena;
    }

    @Test
    void withSeveralRobotsTheResultHasALinePerRobotAndNamesTheOneThatFailed(@TempDir Path dir) throws Exception {
        String arena = threeRobots(dir).toString();
        assertEquals(1, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot",
                "2:controller=org.kheperasim.testcontrollers.Thrower", "--seconds", "5", "--seed", "3"));
        String[] lines = out.strip().split("\\R");
        int head = lines.length - 4;
        assertTrue(lines[head].startsWith("Braitenberg in three: 5.0 s simulated in ") && lines[head].endsWith("; 3 robots"), out);
        assertTrue(lines[head + 1].startsWith("  robot 0 (Braitenberg#0): ended at (") && lines[head + 1].endsWith("controller stopped"), out);
        assertTrue(lines[head + 2].startsWith("  robot 1 (Braitenberg#1): ended at ("), out);
        assertTrue(lines[head + 3].startsWith("  robot 2 (Thrower#2): ended at (") && lines[head + 3].endsWith("controller failed"), out);
        assertTrue(err.contains("] ERROR Thrower#2: threw java.lang.ArithmeticException"), "the error names the robot: " + err);
    }

    @Test
    void theJsonSaysWhyEachRobotFailed(@TempDir Path dir) throws Exception {
        // Exiter calls System.exit after 20 simulated seconds.
        String arena = threeRobots(dir).toString();
        assertEquals(1, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot",
                "1:controller=org.kheperasim.testcontrollers.Exiter", "--robot", "2:controller=org.kheperasim.testcontrollers.Thrower",
                "--seconds", "25", "--seed", "3", "--json"));
        assertTrue(out.contains("\"name\":\"Braitenberg#0\",") && out.contains("\"controllerStatus\":\"stopped\",\"failure\":null}"), out);
        assertTrue(out.contains("\"controllerStatus\":\"broke_rule\",\"failure\":\"controller Exiter#1 (org.kheperasim.testcontrollers.Exiter) called System.exit("), out);
        assertTrue(out.contains("\"controllerStatus\":\"failed\",\"failure\":\"java.lang.ArithmeticException"), out);
        // Where it threw, in the student's code, and when: the grade report and a run's page name the line.
        assertTrue(out.contains("/ by zero\",\"failureAt\":\"org.kheperasim.testcontrollers.Thrower.run(Thrower.java:24)\","
                + "\"failureSeconds\":1.0"), out);
        assertTrue(!out.contains("Exiter.run(Exiter.java"), "System.exit is not a throw: " + out);
    }

    @Test
    void aWrongRobotOptionNamesTheRobotAndTheOption(@TempDir Path dir) throws Exception {
        String arena = threeRobots(dir).toString();
        assertEquals(2, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot", "1:controller=WallFolower"));
        assertTrue(err.contains("robot 1's controller: no controller named 'WallFolower'"), err);
        assertEquals(2, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot", "1:controller=WallFollower",
                "--robot", "1:controller=Aggregation"));
        assertTrue(err.contains("--robot '1:controller=Aggregation': robot 1's controller is given twice"), err);
        assertEquals(2, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot", "2:motor.left.calibraton=0.5"));
        assertTrue(err.contains("--robot '2:motor.left.calibraton=0.5': unknown setting 'motor.left.calibraton'"), err);
        assertEquals(2, main("run", "--arena", arena, "--controller", "Braitenberg", "--robot", "1:engine.stepping=tick"));
        assertTrue(err.contains("engine.stepping is one setting for the whole run, not per robot; give it with --set"), err);
    }

    @Test
    void servingSeveralRobotsSaysWhichPortsTheyNeed(@TempDir Path dir) throws Exception {
        assertEquals(2, main("serve", "--arena", threeRobots(dir).toString(), "--port", "65534", "--seconds", "1"));
        assertTrue(err.contains("--port 65534: the arena's 3 robots need ports 65534..65536, which must lie in 1..65535"), err);
    }

    @Test
    void benchOfAFailingControllerSaysSoAndExitsWithOne() {
        assertEquals(1, main("bench", "--robots", "2", "--controller", "org.kheperasim.testcontrollers.Thrower", "--seconds", "5",
                "--runs", "1", "--warm-up", "0"));
        assertTrue(err.contains("robot 0's controller (Thrower#0) ended failed in the first run"), err);
        assertTrue(err.contains("ERROR Thrower#0: threw java.lang.ArithmeticException"), err);
    }

    @Test
    void benchPrintsSimulatedSecondsPerWallSecond() {
        assertEquals(0, main("bench", "--seconds", "20", "--runs", "1", "--warm-up", "0"));
        assertTrue(out.contains("warm-up: 1 run in "), out);
        assertTrue(out.contains("median: "), out);
        assertTrue(out.contains("simulated seconds per wall second"), out);
        // Figures are only comparable under a similar load: the load is printed with them.
        assertTrue(out.contains("machine load: "), out);
    }

    /**
     * The swarm benchmark's memory line counts what a run holds while it runs: 400 robots hold
     * tens of MB more than one (each its sensors, noise streams, coverage), measured in a run that
     * is still alive, not after it has been dropped.
     */
    @Test
    void swarmBenchPrintsTheHeapARunHolds() {
        assertEquals(0, main("bench", "--robots", "1", "--controller", "StepBraitenberg", "--seconds", "0.1", "--runs", "1",
                "--warm-up", "0"));
        long one = liveMb(out);
        assertEquals(0, main("bench", "--robots", "400", "--controller", "StepBraitenberg", "--seconds", "0.1", "--runs", "1",
                "--warm-up", "0"));
        long many = liveMb(out);
        assertTrue(many > one + 10, "live heap of a run: 1 robot " + one + " MB, 400 robots " + many + " MB");
    }

    private static long liveMb(String out) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("live while a run is set up, after a full collection: ([\\d,]+) MB")
                .matcher(out);
        assertTrue(m.find(), out);
        return Long.parseLong(m.group(1).replace(",", ""));
    }
}
