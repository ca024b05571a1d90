package org.kheperasim.link.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeRobotOnPty;
import org.kheperasim.link.robot.RobotRun;
import org.kheperasim.link.session.Session;

/**
 * The commands a lab user types, against the fake robot on a pty pair.
 *
 * <p>Tagged {@code timing}: real time over a serial line (a pty pair); {@code .ci/run} runs it again
 * with both cores busy.
 */
@Tag("timing")
@Timeout(value = 90, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CliPtyTest {
    @TempDir
    Path dir;

    private String out;
    private String err;

    private int main(String input, String... args) {
        StringWriter o = new StringWriter();
        StringWriter e = new StringWriter();
        int code = Main.execute(args, new ByteArrayInputStream(input.getBytes(StandardCharsets.UTF_8)),
                new PrintWriter(o), new PrintWriter(e));
        out = o.toString();
        err = e.toString();
        return code;
    }

    @Test
    void checkExercisesEveryCommandAndPrintsATable() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            int code = main("", "check", "--port", fake.hostPath(), "--baud", "38400", "--bus-write", "0,0");
            assertEquals(0, code, out + err);
            for (String c : List.of("A,3800,800,100", "B ", "C,0,0", "D,0,0", "E ", "F,3000,20,4000", "G,0,0", "H ",
                    "I,0", "J,20,64,20,64", "K ", "L,0,0", "N ", "O ", "P,0,0", "R,0", "W,0,0", "T,1,B", "T,1,G",
                    "T,1,F", "T,1,H,0", "T,1,H,1", "T,1,D,0", "T,1,E,180")) {
                assertTrue(out.lines().anyMatch(l -> l.startsWith(c) && l.contains(" ok ")), c + " in\n" + out);
            }
            assertTrue(out.contains("24 of 24 commands answered"), out);
            assertEquals("D,0,0", fake.robot().lastReceived());
        }
    }

    @Test
    void checkShowsWhatTheRobotRefuses() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            fake.robot().setGripperFitted(false);
            // Refusals come at once; the timeout only waits out a reply a loaded machine delays.
            int code = main("", "check", "--port", fake.hostPath(), "--timeout", "1000");
            assertEquals(1, code, out + err);
            assertTrue(out.lines().anyMatch(l -> l.startsWith("T,1,G") && l.contains("REFUSED")
                    && l.contains("Command not found")), out);
            assertTrue(out.contains("16 of 23 commands answered"), out);
            assertEquals("D,0,0", fake.robot().lastReceived());
        }
    }

    @Test
    void consoleSendsRawLinesAndShowsReplies() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            fake.robot().setProximity(1, 2, 3, 4, 5, 6, 7, 8);
            int code = main("N\nD,3,3\nX\nD,300,0\n\n", "console", "--port", fake.hostPath());
            assertEquals(0, code, out + err);
            assertTrue(out.contains("robot answers: BIOS 5.02, protocol 5.01"), out);
            assertTrue(out.contains("< n,1,2,3,4,5,6,7,8"), out);
            assertTrue(out.contains("< d"), out);
            assertTrue(out.contains("< Command not found"), out);
            assertTrue(out.contains("< z,Protocol error"), out);
            assertTrue(out.contains("sent D,0,0"), out);
            assertEquals("D,0,0", fake.robot().lastReceived());
        }
    }

    @Test
    void runDrivesTheRobotWithABundledControllerAndRecords() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            Path rec = dir.resolve("run.txt");
            int code = main("", "run", "--port", fake.hostPath(), "--baud", "9600", "--controller", "WallFollower",
                    "--seconds", "1", "--record", rec.toString());
            assertEquals(0, code, out + err);
            assertTrue(out.contains("running org.kheperasim.controllers.WallFollower for 1.0 s"), out);
            assertTrue(out.contains("robot stopped (D,0,0 acknowledged)"), out);
            assertTrue(fake.robot().received().contains("D,3,3"));
            assertEquals("D,0,0", fake.robot().lastReceived());
            List<String> lines = Files.readAllLines(rec);
            assertTrue(lines.size() > 5 && lines.get(2).startsWith("# t_s"), lines.toString());
            List<String> samples = lines.stream().filter(l -> !l.startsWith("#") && !l.startsWith(">")
                    && !l.startsWith("<")).toList();
            assertTrue(samples.size() > 3, lines.toString());
            assertEquals(21, samples.get(samples.size() - 1).split(" ").length, samples.get(samples.size() - 1));
            // Every line sent and received is kept too, with its time.
            assertTrue(lines.stream().anyMatch(l -> l.matches("> [0-9.]+ D,3,3")), lines.toString());
            assertTrue(lines.stream().anyMatch(l -> l.matches("< [0-9.]+ n(,[0-9]+){8}")), lines.toString());
        }
    }

    @Test
    void errorsNameTheThingAndTheFix() {
        assertEquals(2, main("", "run", "--port", dir.resolve("nope").toString(), "--controller", "WallFollower"));
        assertTrue(err.contains("cannot open serial port") && err.contains("does not exist"), err);
        assertEquals(2, main("", "run", "--port", "/dev/null", "--controller", "WallFolower"));
        assertTrue(err.contains("no controller named 'WallFolower'") && err.contains("WallFollower"), err);
        assertEquals(2, main("", "check", "--port", "tcp://localhost"));
        assertTrue(err.contains("tcp://HOST:PORT"), err);
    }

    @Test
    void theShutdownHookStopsTheRobotWhenTheProgramIsKilled() throws Exception {
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, null)) {
            String cp = System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
            // The quick compiler only: the JVM lives a second or two, and C2 would spend most of its processor time.
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-XX:TieredStopAtLevel=1", "-cp", cp, Main.class.getName(), "run", "--port", fake.hostPath(), "--controller",
                    "org.kheperasim.link.testcontrollers.Forward"));
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile())
                    .start();
            try {
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (!fake.robot().received().contains("D,5,5") && System.nanoTime() < end) {
                    Thread.sleep(20);
                }
                assertTrue(fake.robot().received().contains("D,5,5"), Files.readString(dir.resolve("out.txt")));
                p.destroy(); // SIGTERM, as Ctrl-C's SIGINT: the JVM runs its shutdown hooks
                assertTrue(p.waitFor(20, TimeUnit.SECONDS));
            } finally {
                p.destroyForcibly();
            }
            Thread.sleep(200);
            String printed = Files.readString(dir.resolve("out.txt"));
            assertEquals("D,0,0", fake.robot().lastReceived(), printed);
            assertTrue(fake.robot().speeds()[0] == 0);
            // The user at the robot is told, as on a normal end, that the robot confirmed its stop.
            assertTrue(printed.contains("ended: stopped by a signal") || printed.contains("ended: the program is exiting"),
                    printed);
            assertTrue(printed.contains("robot stopped (D,0,0 acknowledged)"), printed);
            assertEquals(143, p.exitValue(), printed);
        }
    }

    @Test
    void anEndWhoseStopTheRobotDidNotConfirmIsNotASuccess() {
        Session.Stats none = new Session.Stats(0, 0, 0, 0, 0, 0);
        for (RobotRun.End end : RobotRun.End.values()) {
            RobotRun.Result confirmed = new RobotRun.Result(end, "", 0, none, true, null);
            RobotRun.Result unconfirmed = new RobotRun.Result(end, "", 0, none, false, null);
            assertEquals(1, RunCommand.exitStatus(unconfirmed), end + " without D,0,0 acknowledged");
            boolean ok = end == RobotRun.End.FINISHED || end == RobotRun.End.TIME_UP || end == RobotRun.End.STOPPED;
            assertEquals(ok ? 0 : 1, RunCommand.exitStatus(confirmed), end.toString());
        }
    }
}
