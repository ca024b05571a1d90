package org.kheperasim.sim.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code run --sandbox} and {@code serve --sandbox} put a single run in the box grade uses: a
 * controller that escapes its JVM's rules ({@code --trusted}) finds no network and no /etc/passwd,
 * while the run's trace is still written where it was asked for; a served robot still answers its
 * clients (serve keeps the network). And where there is no box, the refusal says why and what to do.
 */
class SandboxCommandsTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void runSandboxKeepsAnEscapingControllerInTheBoxAndWritesItsTrace() throws Exception {
        requireBox();
        Path src = dir.resolve("src");
        Files.createDirectories(src);
        Files.writeString(src.resolve("Peeker.java"), """
                import org.kheperasim.api.*;

                public class Peeker extends Controller {
                    @Override
                    protected void doWork() {
                        String passwd;
                        try {
                            passwd = java.nio.file.Files.readString(java.nio.file.Path.of("/etc/passwd")).isEmpty() ? "empty" : "read";
                        } catch (java.io.IOException e) {
                            passwd = "absent";
                        }
                        String net;
                        try (java.net.Socket s = new java.net.Socket()) {
                            s.connect(new java.net.InetSocketAddress("1.1.1.1", 53), 2000);
                            net = "connected";
                        } catch (java.io.IOException e) {
                            net = "unreachable";
                        }
                        System.err.println("PEEK passwd=" + passwd + " net=" + net + " home=" + System.getProperty("user.home"));
                        setSpeeds(4, 4);
                        sleepMillis(5000);
                    }
                }
                """);
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), src.resolve("Peeker.java").toString()));
        Path trace = dir.resolve("traces/peek.trace");
        Process p = sim("run", "--sandbox", "--trusted", "--arena", "lab", "--classpath", classes.toString(), "--controller",
                "Peeker", "--seconds", "3", "--seed", "2", "--trace", trace.toString());
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(90, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        assertTrue(out.contains("PEEK passwd=absent net=unreachable home=/tmp"), out);
        assertTrue(out.contains("Peeker in lab: 3.0 s simulated"), out);
        List<String> lines = Files.readAllLines(trace);
        assertEquals("# khepera-trace 2", lines.get(0));
        assertEquals(3000 / 50 + 1, lines.stream().filter(l -> !l.startsWith("#")).count(), "every sample, written from the box");
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void serveSandboxStillAnswersItsClients() throws Exception {
        requireBox();
        Process p = sim("serve", "--sandbox", "--arena", "lab", "--port", "0", "--seconds", "60");
        try {
            BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            Pattern url = Pattern.compile("at tcp://127\\.0\\.0\\.1:(\\d+)");
            int port = -1;
            StringBuilder seen = new StringBuilder();
            for (String l = in.readLine(); l != null && port < 0; l = in.readLine()) {
                seen.append(l).append('\n');
                Matcher m = url.matcher(l);
                if (m.find()) {
                    port = Integer.parseInt(m.group(1));
                }
            }
            if (port < 0) {
                fail("serve printed no address: " + seen);
            }
            try (Socket s = new Socket("127.0.0.1", port)) {
                s.setSoTimeout(10_000);
                OutputStream o = s.getOutputStream();
                o.write("N\r\n".getBytes(StandardCharsets.US_ASCII));
                o.flush();
                String reply = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.US_ASCII)).readLine();
                assertTrue(reply != null && reply.startsWith("n,"), "the served robot's proximity reply: " + reply);
            }
        } finally {
            p.destroy();
            assertTrue(p.waitFor(30, TimeUnit.SECONDS), "serve --sandbox stops on SIGTERM");
        }
    }

    @Test
    void withoutABoxTheRefusalSaysWhyAndWhatToDo() {
        String userns = BoxProbe.explain("bwrap: No permissions to creating new namespace, likely because the kernel does not"
                + " allow non-privileged user namespaces. On e.g. debian this can be enabled with 'sysctl"
                + " kernel.unprivileged_userns_clone=1'.");
        assertTrue(userns.contains("kernel.apparmor_restrict_unprivileged_userns=0")
                && userns.contains("kernel.unprivileged_userns_clone=1"), userns);
        String refusal = BoxProbe.refusal("grade", "bubblewrap (bwrap) is not installed: install it (Debian, Ubuntu:"
                + " apt-get install bubblewrap; Fedora: dnf install bubblewrap)");
        assertTrue(refusal.startsWith("grade runs code that is not your own in a bubblewrap sandbox, but bubblewrap (bwrap) is"
                + " not installed"), refusal);
        assertTrue(refusal.contains("give --no-sandbox"), refusal);
    }

    private static Process sim(String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main"));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true).start();
    }

    static void requireBox() {
        BoxProbe.unavailable().ifPresent(reason -> {
            if ("true".equals(System.getenv("CI"))) {
                fail("no sandbox: " + reason + "; CI=true requires the sandbox tests to run (apt-get install -y bubblewrap)");
            }
            Assumptions.assumeTrue(false, "no sandbox (" + reason + "); sandbox test skipped");
        });
    }
}
