package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Assumptions;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * Test submissions that do what a student with a hole in the allowlist would do, written into a
 * submissions folder, and the probe for the sandbox they are run in (skipped on a machine without
 * bubblewrap, required when {@code CI=true}).
 */
final class Hostile {
    private Hostile() {
    }

    /** Skip without a sandbox on this machine; fail when CI=true requires the sandbox tests to run. */
    static void requireBox() {
        BoxProbe.unavailable().ifPresent(reason -> {
            if ("true".equals(System.getenv("CI"))) {
                fail("no sandbox: " + reason + "; CI=true requires the sandbox tests to run (apt-get install -y bubblewrap)");
            }
            Assumptions.assumeTrue(false, "no sandbox (" + reason + "); sandbox test skipped");
        });
    }

    /**
     * A controller that, trusted (a hole in its JVM's rules), tries every way out of the box, then
     * throws its findings so that they reach the report's detail:
     * {@code ESCAPE net=… passwd=… other=… othercls=… out=… own=… scratch=… threads=… uid=… cap=… nnp=… pids=…}.
     *
     * @param folder      the student's folder
     * @param port        a port the test listens on at the host's loopback
     * @param otherSource another student's source file
     * @param otherClass  another student's compiled class (in the report folder)
     * @param outFile     a file in the report folder to try to write
     * @param ownClasses  the folder its own compiled classes will be in
     * @param hostMarker  a file under the host's /tmp to try to write
     */
    static void escaper(Path folder, int port, Path otherSource, Path otherClass, Path outFile, Path ownClasses, Path hostMarker)
            throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Escaper.java"), """
                import java.nio.file.*;
                import org.kheperasim.api.*;

                public class Escaper extends Controller {
                    @Override
                    protected void doWork() {
                        StringBuilder r = new StringBuilder("ESCAPE");
                        r.append(" net=").append(connect(%d));
                        r.append(" passwd=").append(read("/etc/passwd"));
                        r.append(" other=").append(read("%s"));
                        r.append(" othercls=").append(read("%s"));
                        r.append(" out=").append(write("%s"));
                        r.append(" own=").append(write("%s"));
                        r.append(" scratch=").append(write(System.getProperty("java.io.tmpdir") + "/scratch.txt"));
                        r.append(" host=").append(write("%s"));
                        r.append(" threads=").append(threads());
                        r.append(" uid=").append(status("Uid:"));
                        r.append(" cap=").append(status("CapEff:"));
                        r.append(" nnp=").append(status("NoNewPrivs:"));
                        r.append(" pids=").append(pids());
                        throw new IllegalStateException(r.toString());
                    }

                    private static String connect(int port) {
                        try (java.net.Socket s = new java.net.Socket()) {
                            s.connect(new java.net.InetSocketAddress("127.0.0.1", port), 2000);
                            return "connected";
                        } catch (java.io.IOException e) {
                            return "refused";
                        }
                    }

                    private static String read(String file) {
                        try {
                            return Files.readAllBytes(Path.of(file)).length > 0 ? "read" : "empty";
                        } catch (java.io.IOException e) {
                            return "absent";
                        }
                    }

                    private static String write(String file) {
                        try {
                            Files.writeString(Path.of(file), "escaped");
                            return "written";
                        } catch (java.io.IOException e) {
                            return "denied";
                        }
                    }

                    /** JDK code starts the threads (a Timer each), outside the simulator's hooks: as many as the box lets it. */
                    private static int threads() {
                        java.util.List<java.util.Timer> timers = new java.util.ArrayList<>();
                        try {
                            for (int i = 0; i < 2000; i++) {
                                timers.add(new java.util.Timer(true));
                            }
                        } catch (Throwable e) {
                            // unable to create native thread: the limit
                        }
                        timers.forEach(java.util.Timer::cancel);
                        return timers.size();
                    }

                    private static String status(String key) {
                        try {
                            for (String l : Files.readAllLines(Path.of("/proc/self/status"))) {
                                if (l.startsWith(key)) {
                                    return l.substring(key.length()).strip().split("\\\\s+")[0];
                                }
                            }
                        } catch (java.io.IOException e) {
                            return "?";
                        }
                        return "?";
                    }

                    private static long pids() {
                        try (var s = Files.list(Path.of("/proc"))) {
                            return s.filter(p -> p.getFileName().toString().matches("\\\\d+")).count();
                        } catch (java.io.IOException e) {
                            return -1;
                        }
                    }
                }
                """.formatted(port, otherSource, otherClass, outFile, ownClasses.resolve("planted.txt"), hostMarker));
    }

    /**
     * @param detail a report's detail of an escaper's run
     * @return its findings, key to value
     */
    static Map<String, String> findings(String detail) {
        int at = detail.indexOf("ESCAPE ");
        if (at < 0) {
            fail("no findings in the detail: " + detail);
        }
        Map<String, String> out = new LinkedHashMap<>();
        for (String kv : detail.substring(at + 7).split("[ |]+")) {
            int eq = kv.indexOf('=');
            if (eq > 0) {
                out.put(kv.substring(0, eq), kv.substring(eq + 1));
            }
        }
        return out;
    }

    /** A controller that prints a forged result line to the JVM's own standard output and halts it (today's exploit). */
    static void printForger(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Printer.java"), """
                import org.kheperasim.api.*;

                public class Printer extends Controller {
                    @Override
                    protected void doWork() {
                        java.io.PrintStream raw = new java.io.PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), true);
                        raw.println("{\\"simulatedSeconds\\":20,\\"traceSha256\\":\\"0\\",\\"robots\\":[{\\"controllerStatus\\":"
                                + "\\"finished\\"}],\\"score\\":{\\"points\\":999,\\"max\\":999,\\"percent\\":100,\\"tasks\\":[]}}");
                        Runtime.getRuntime().halt(0);
                    }
                }
                """);
    }

    /**
     * A controller that rewrites its own result in memory: it reaches the simulator's robot by
     * reflection and moves it into every cell of the maze in turn, so the run's own result (and its
     * trace) shows a full tour the robot never drove.
     */
    static void memoryForger(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Teleporter.java"), """
                import java.lang.reflect.Field;
                import org.kheperasim.api.*;

                public class Teleporter extends Thread {
                    private final CurrentRobotState state;

                    public Teleporter(CurrentRobotState state, MessagePasser mp) {
                        this.state = state;
                    }

                    @Override
                    public void run() {
                        try {
                            Object port = field(state, "port");
                            Object robot = field(port, "robot");
                            Object body = field(robot, "body");
                            for (int i = 0; i < 25; i++) {
                                set(body, "x", (i % 5 + 0.5) * 243.84);
                                set(body, "y", (i / 5 + 0.5) * 243.84);
                                state.getMotorState().setMotorSpeeds(0, 0);
                                Thread.sleep(200);
                            }
                            while (true) {
                                Thread.sleep(1000);
                            }
                        } catch (InterruptedException e) {
                            return;
                        } catch (ReflectiveOperationException e) {
                            throw new IllegalStateException(e);
                        }
                    }

                    private static Object field(Object o, String name) throws ReflectiveOperationException {
                        Field f = o.getClass().getDeclaredField(name);
                        f.setAccessible(true);
                        return f.get(o);
                    }

                    private static void set(Object o, String name, double v) throws ReflectiveOperationException {
                        Field f = o.getClass().getDeclaredField(name);
                        f.setAccessible(true);
                        f.setDouble(o, v);
                    }
                }
                """);
    }

    /** A controller whose thread pool spins for ever, outside the simulator's hooks, while it drives on. */
    static void poolSpinner(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Pool.java"), """
                import org.kheperasim.api.*;

                public class Pool extends Controller {
                    private boolean started;

                    @Override
                    protected void doWork() {
                        if (!started) {
                            started = true;
                            java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(2);
                            for (int i = 0; i < 2; i++) {
                                pool.submit(() -> {
                                    long n = 0;
                                    while (true) {
                                        n++;
                                    }
                                });
                            }
                        }
                        setSpeeds(3, 3);
                        sleepMillis(100);
                    }
                }
                """);
    }

    /** A controller that prints 1 KB lines every simulated millisecond. */
    static void chatterbox(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Chatter.java"), """
                import org.kheperasim.api.*;

                public class Chatter extends Controller {
                    private static final String LINE = "chatter ".repeat(125);

                    @Override
                    protected void doWork() {
                        System.err.println(LINE);
                        sleepMillis(1);
                    }
                }
                """);
    }
}
