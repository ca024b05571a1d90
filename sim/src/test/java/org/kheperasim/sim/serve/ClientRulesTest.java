package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;

/** One client per robot, the robot stops when it leaves, and abuse does not hurt the server. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@Tag("timing")
class ClientRulesTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);

    private static void waitUntil(String what, java.util.function.BooleanSupplier condition) throws InterruptedException {
        // Generous: on a loaded machine the served robot's thread may wait long for a core.
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!condition.getAsBoolean()) {
            assertTrue(System.nanoTime() < end, "in 30 s: " + what);
            Thread.sleep(5);
        }
    }

    private static int speedLeft(Served s) {
        return s.robot.inspect(SimRobot::speedLeft);
    }

    @Test
    void theRobotStopsWhenItsClientGoesAwayAndWaitsForTheNext() throws Exception {
        try (Served s = new Served("", EXACT, 1)) {
            List<ProtocolServer.Event> events = new java.util.concurrent.CopyOnWriteArrayList<>();
            s.server.addListener(events::add);
            LineClient c = s.client();
            assertEquals("d", c.ask("D,10,10"));
            assertEquals("c", c.ask("C,100000,100000"));
            assertEquals("d", c.ask("D,10,10"));
            waitUntil("it drives", () -> s.robot.snapshot().robots().get(0).x() > 300);
            assertEquals(10, speedLeft(s));
            c.close();
            waitUntil("the robot stops when the client closes", () -> speedLeft(s) == 0
                    && s.robot.inspect(SimRobot::speedRight) == 0);
            waitUntil("the slot frees", () -> s.server.client() == null);
            double x1 = s.robot.snapshot().robots().get(0).x();
            Thread.sleep(200);
            assertEquals(x1, s.robot.snapshot().robots().get(0).x(), 1e-9, "and stays stopped");
            assertTrue(events.stream().anyMatch(e -> e.kind() == ProtocolServer.EventKind.DISCONNECTED
                    && e.text().contains("the robot stopped")), events.toString());

            // A client that vanishes mid-move (socket reset) stops it too; then a new client is served.
            Socket rude = new Socket(InetAddress.getLoopbackAddress(), s.server.port());
            rude.getOutputStream().write("C,-50000,-50000\n".getBytes(StandardCharsets.US_ASCII));
            rude.setSoLinger(true, 0);
            waitUntil("the position move runs", () -> speedLeft(s) < 0);
            rude.close();
            waitUntil("the robot stops after a reset", () -> speedLeft(s) == 0);
            assertEquals(0, (int) s.robot.inspect(r -> r.onBoard().motionStatus()[1]), "and leaves position mode");
            waitUntil("the slot frees", () -> s.server.client() == null);
            try (LineClient next = s.client()) {
                assertEquals("b,5.02,5.01", next.ask("B"));
            }
        }
    }

    @Test
    void aSecondClientIsRefusedWithOneClearLine() throws Exception {
        try (Served s = new Served("", EXACT, 1); LineClient first = s.client()) {
            assertEquals("b,5.02,5.01", first.ask("B"));
            String who = s.server.client();
            assertTrue(who.startsWith("127.0.0.1:"), who);
            try (LineClient second = s.client()) {
                assertEquals("z,Busy: robot already has a client from " + who, second.readLine());
                assertNull(second.readLine(), "then the connection closes");
            }
            assertEquals("b,5.02,5.01", first.ask("B"), "the first client is not disturbed");
        }
    }

    @Test
    void garbageBinaryNoiseAndAnEndlessLineGetAnswersNotACrash() throws Exception {
        try (Served s = new Served("", EXACT, 20); LineClient c = s.client()) {
            for (String junk : new String[] {"hello", "123", ",,,", "D,,", "D,1,2,3", "N,", "T", "T,,", "T,1,",
                "T,x,G", "D,99999999999,1", "D,-,1", " D,1,1", "ÿÿÿ", "G,2147483648,0"}) {
                String r = c.ask(junk);
                assertTrue(r.equals("Command not found") || r.equals("z,Protocol error"), junk + " -> " + r);
            }
            // Binary noise: every byte value, many times, then a proper command.
            Random random = new Random(7);
            byte[] noise = new byte[20000];
            random.nextBytes(noise);
            c.sendBytes(noise);
            c.send("\nB\n");
            String line;
            int answers = 0;
            while (!(line = c.readLine()).equals("b,5.02,5.01")) {
                assertTrue(line.equals("Command not found") || line.equals("z,Protocol error")
                        || line.startsWith("k,") || line.startsWith("n,") || line.startsWith("o,")
                        || line.startsWith("e,") || line.startsWith("h,") || line.length() <= 12,
                        "an answer to noise: " + line);
                answers++;
            }
            assertTrue(answers > 0, "the noise was answered, line by line");
            assertEquals("d", c.ask("D,0,0"), "noise may have moved the wheels; stop them");

            // 64 KiB without a line end: one refusal, nothing stored, the next line is served.
            byte[] endless = new byte[64 * 1024];
            Arrays.fill(endless, (byte) 'N');
            c.sendBytes(endless);
            assertEquals("z,Protocol error", c.readLine(), "an overlong line is refused once");
            assertTrue(c.silentFor(300), "and nothing more until its end");
            c.sendBytes(endless);
            c.send("\nB\n");
            assertEquals("b,5.02,5.01", c.readLine(), "the rest of the line is dropped; the next one served");
        }
    }

    private static int threads() {
        return ManagementFactory.getThreadMXBean().getThreadCount();
    }

    private static long openFiles() {
        java.lang.management.OperatingSystemMXBean os = ManagementFactory.getOperatingSystemMXBean();
        return os instanceof com.sun.management.UnixOperatingSystemMXBean u ? u.getOpenFileDescriptorCount() : -1;
    }

    @Test
    void rapidConnectsAndAHundredAtOnceLeakNothing() throws Exception {
        try (Served s = new Served("", EXACT, 20)) {
            try (LineClient warm = s.client()) {
                assertEquals("b,5.02,5.01", warm.ask("B"));
            }
            waitUntil("slot free", () -> s.server.client() == null);
            Thread.sleep(100);
            int threads0 = threads();
            long files0 = openFiles();

            for (int i = 0; i < 200; i++) {
                try (Socket k = new Socket(InetAddress.getLoopbackAddress(), s.server.port())) {
                    if (i % 2 == 0) {
                        k.getOutputStream().write("D,5,5\nN".getBytes(StandardCharsets.US_ASCII));
                    }
                }
            }

            int clients = 100;
            ExecutorService pool = Executors.newFixedThreadPool(clients);
            CountDownLatch go = new CountDownLatch(1);
            List<Future<String>> results = new ArrayList<>();
            List<Socket> sockets = java.util.Collections.synchronizedList(new ArrayList<>());
            for (int i = 0; i < clients; i++) {
                results.add(pool.submit(() -> {
                    go.await();
                    Socket k = new Socket(InetAddress.getLoopbackAddress(), s.server.port());
                    sockets.add(k);
                    k.setSoTimeout(2000);
                    LineClientOn on = new LineClientOn(k);
                    try {
                        return on.readLine();
                    } catch (java.net.SocketTimeoutException e) {
                        return "SERVED";
                    }
                }));
            }
            go.countDown();
            int busy = 0;
            int served = 0;
            for (Future<String> f : results) {
                String r = f.get(30, TimeUnit.SECONDS);
                if ("SERVED".equals(r)) {
                    served++;
                } else if (r != null && r.startsWith("z,Busy: robot already has a client from 127.0.0.1:")) {
                    busy++;
                }
            }
            assertEquals(1, served, "exactly one is served");
            assertEquals(clients - 1, busy, "every other one is told the robot is busy");
            for (Socket k : sockets) {
                k.close();
            }
            pool.shutdown();
            assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
            waitUntil("slot free", () -> s.server.client() == null);
            try (LineClient after = s.client()) {
                assertEquals("b,5.02,5.01", after.ask("B"), "a proper client is served afterwards");
                assertEquals("e,0,0", after.ask("E"), "the robot stopped when the clients left");
            }
            waitUntil("threads back to " + threads0 + " (now " + threads() + ")", () -> threads() <= threads0);
            if (files0 >= 0) {
                waitUntil("open files back to " + files0 + " (now " + openFiles() + ")", () -> openFiles() <= files0);
            }
        }
    }

    /** Reads one line from a socket that is already open. */
    private static final class LineClientOn {
        private final java.io.InputStream in;

        LineClientOn(Socket s) throws IOException {
            in = s.getInputStream();
        }

        String readLine() throws IOException {
            StringBuilder b = new StringBuilder();
            int c;
            while ((c = in.read()) >= 0 && c != '\n') {
                if (c != '\r') {
                    b.append((char) c);
                }
            }
            return c < 0 && b.length() == 0 ? null : b.toString();
        }
    }
}
