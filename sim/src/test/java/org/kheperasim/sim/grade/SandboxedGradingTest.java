package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.Box;
import org.kheperasim.sim.sandbox.BoxLimits;

/**
 * A graded controller that has escaped its JVM's rules (run trusted: the hole a test opens on
 * purpose) still meets the operating-system box: no network, no /etc/passwd, no other submission,
 * nothing written outside its scratch folder, no more threads than its limit, no capabilities, its
 * own process namespace; the same controller without the box reaches all of it, which is what shows
 * the probes bite. Run as root in CI, where the limits must hold for root too.
 */
class SandboxedGradingTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aControllerThatEscapesItsJvmStillMeetsTheBox() throws IOException {
        Hostile.requireBox();
        Map<String, String> f = escape(true);
        System.out.println("in the box: " + f);
        assertEquals("refused", f.get("net"), "no network: " + f);
        assertEquals("absent", f.get("passwd"), "no /etc: " + f);
        assertEquals("absent", f.get("other"), "no other submission's source: " + f);
        assertEquals("absent", f.get("othercls"), "no other submission's classes: " + f);
        assertEquals("denied", f.get("out"), "nothing written in the report folder: " + f);
        assertEquals("denied", f.get("own"), "its own classes are read-only: " + f);
        assertEquals("written", f.get("scratch"), "its scratch folder takes a file: " + f);
        int threads = Integer.parseInt(f.get("threads"));
        int limit = BoxLimits.forRun(128, 1, 120).processes();
        assertTrue(threads > 5 && threads < limit, threads + " threads started, the box allows " + limit + " with the JVM's own");
        assertEquals("0000000000000000", f.get("cap"), "no capabilities: " + f);
        assertEquals("1", f.get("nnp"), "no new privileges: " + f);
        if (Box.isRoot()) {
            assertNotEquals("0", f.get("uid"), "a root grader's box runs as a user of its own: " + f);
        }
        assertTrue(Integer.parseInt(f.get("pids")) <= 3, "only the box's own processes are visible: " + f);
    }

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void withoutTheBoxTheSameControllerReachesEverything() throws IOException {
        Map<String, String> f = escape(false);
        System.out.println("without the box: " + f);
        assertEquals("connected", f.get("net"), f.toString());
        assertEquals("read", f.get("passwd"), f.toString());
        assertEquals("read", f.get("other"), f.toString());
        assertEquals("read", f.get("othercls"), f.toString());
        assertEquals("written", f.get("out"), f.toString());
        assertEquals("written", f.get("own"), f.toString());
        assertTrue(Integer.parseInt(f.get("threads")) > 500, f.toString());
    }

    /** Grades the escaper beside an honest student, trusted, with or without the box; its findings. */
    private Map<String, String> escape(boolean sandbox) throws IOException {
        Path subs = dir.resolve("subs");
        Path out = dir.resolve("out");
        Path bob = Files.createDirectories(subs.resolve("bob"));
        for (String f : List.of("Robot.java", "Turns.java")) {
            Files.copy(Path.of("src/test/resources/grade/bob", f), bob.resolve(f));
        }
        Path hostMarker = Path.of("/tmp", "khepera-escape-" + UUID.randomUUID());
        try (ServerSocket listener = new ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            listener.setSoTimeout(1);
            Hostile.escaper(subs.resolve("mallory"), listener.getLocalPort(), bob.resolve("Robot.java").toAbsolutePath(),
                    out.resolve("work/bob/classes/Robot.class").toAbsolutePath(), out.resolve("escaped.txt").toAbsolutePath(),
                    out.resolve("work/mallory/classes").toAbsolutePath(), hostMarker);
            ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("maze"), 1, 2, out, GradePlan.Shard.ALL, 128,
                    120, 20, 5.0, false, new PrintStream(OutputStream.nullOutputStream()), false, sandbox, true));
            RunRecord mallory = report.runs().stream().filter(r -> r.student().equals("mallory")).findFirst().orElseThrow();
            RunRecord honest = report.runs().stream().filter(r -> r.student().equals("bob")).findFirst().orElseThrow();
            assertEquals(RunStatus.OK, honest.status(), honest.toString());
            assertEquals(sandbox ? RunRecord.SANDBOX : RunRecord.NO_SANDBOX, mallory.madeIn());
            assertEquals(RunStatus.THREW, mallory.status(), mallory.toString());
            if (sandbox) {
                assertFalse(Files.exists(hostMarker), "the host's /tmp got nothing: the box's /tmp is its own");
                assertFalse(Files.exists(out.resolve("escaped.txt")));
            }
            return Hostile.findings(mallory.detail());
        } finally {
            Files.deleteIfExists(hostMarker);
        }
    }
}
