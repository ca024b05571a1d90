package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.fake.FakeEpuck;
import org.kheperasim.link.fake.OnSocket;
import org.kheperasim.link.fake.PtyPair;
import org.kheperasim.link.io.Link;
import org.kheperasim.link.io.Links;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * The bundled Braitenberg controller, unchanged, drives the fake e-puck (written from the e-puck's
 * firmware) through robot-link in the {@code epuck} dialect: the session opens with {@code V}, the
 * poll reads {@code N}, {@code O} and the step counters with {@code Q}, the speeds go out as the
 * e-puck's {@code D}, nothing of the Khepera's own ({@code B}, {@code H}, {@code T}) is sent, and
 * {@code D,0,0} is the last thing the robot hears.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class EpuckRunTest {
    @TempDir
    Path dir;

    private final List<String> console = Collections.synchronizedList(new ArrayList<>());
    private final Consumer<String> out = console::add;

    @Test
    void braitenbergDrivesTheFakeEpuckOverItsOwnLetters() throws Exception {
        try (OnSocket<FakeEpuck> robot = OnSocket.start((in, o) -> new FakeEpuck(in, o).start())) {
            Link link = Links.open(SerialSettings.khepera(robot.url(), 115200));
            drive(link, () -> robot.robot());
        }
    }

    /** Over a serial line (a pty pair), as over a Bluetooth serial port: a serial port is a serial port. */
    @Test
    @Tag("timing")
    void braitenbergDrivesTheFakeEpuckOverASerialLine() throws Exception {
        PtyPair pty = PtyPair.open(dir);
        FakeEpuck fake = new FakeEpuck(new FileInputStream(pty.robot().toFile()),
                new FileOutputStream(pty.robot().toFile())).start();
        try {
            drive(SerialLink.open(SerialSettings.khepera(pty.host().toString(), 115200)), () -> fake);
        } finally {
            pty.kill();
            fake.close();
        }
    }

    private interface Robot {
        FakeEpuck get() throws Exception;
    }

    private void drive(Link link, Robot robot) throws Exception {
        Class<?> braitenberg = new ControllerLoader(List.of()).load("Braitenberg");
        try (Session s = new Session(link, LinkTiming.atBaud(115200), new Session.Options(300, 3, 100, 2000),
                Dialect.named("epuck"))) {
            Session.Versions v = s.open();
            assertEquals("Version 1.1.3 September 2006", v.bios());
            RobotBackend backend = new RobotBackend(s, RobotSettings.defaults(), out);
            RobotRun run = new RobotRun(backend, braitenberg, out);
            FakeEpuck fake = robot.get();
            int[] moved = new int[1];
            Thread scene = new Thread(() -> {
                try {
                    await(fake, "D,6,6");                   // nothing in sight: cruising (6, 6)
                    fake.setProximity(0, 0, 700, 0, 0, 0, 0, 0);
                    await(fake, "D,4,-4");                  // something ahead on the left: spin right
                    long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                    while (backend.leftPosition() == 0 && System.nanoTime() < until) {
                        Thread.sleep(10);
                    }
                    moved[0] = backend.leftPosition();
                } catch (Exception e) {
                    console.add("script: " + e);
                } finally {
                    run.requestStop("the moves were seen");
                }
            }, "epuck-scene");
            scene.setDaemon(true);
            scene.start();
            RobotRun.Result r = run.run(40_000);
            scene.join(5000);
            assertEquals(RobotRun.End.STOPPED, r.end(), r.detail() + " " + console);
            List<String> got = fake.received();
            assertEquals("V", got.get(0), "the session opens with the e-puck's version command");
            assertTrue(got.contains("D,6,6") && got.indexOf("D,6,6") < got.indexOf("D,4,-4"),
                    "the moves in order: " + got);
            assertTrue(got.contains("Q") && got.contains("N") && got.contains("O"), "polled with N, O, Q");
            assertTrue(got.stream().noneMatch(l -> l.startsWith("H") || l.startsWith("T") || l.startsWith("B")),
                    "no Khepera letter reached the e-puck: " + RobotScript.tail(got));
            assertTrue(moved[0] != 0, "the wheel positions come from the e-puck's step counters");
            assertEquals("D,0,0", fake.lastReceived(), "stopped last");
            assertTrue(r.stopAcknowledged());
            assertTrue(console.stream().noneMatch(l -> l.startsWith("script:")), "the script: " + console);
        }
    }

    private static void await(FakeEpuck robot, String line) throws InterruptedException {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!robot.received().contains(line)) {
            if (System.nanoTime() > until) {
                throw new AssertionError("the e-puck did not receive " + line + "; the last: "
                        + RobotScript.tail(robot.received()));
            }
            Thread.sleep(5);
        }
    }
}
