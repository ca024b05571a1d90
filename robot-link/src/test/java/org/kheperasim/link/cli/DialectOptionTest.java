package org.kheperasim.link.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fake.FakeEpuck;
import org.kheperasim.link.fake.OnSocket;

/**
 * {@code khepera-link ... --dialect epuck}: {@code run} drives the fake e-puck with a bundled
 * controller, {@code check} runs the e-puck's commands; a wrong name, a clamp above the robot's
 * limit and a gripper on an e-puck are refused with exit 2.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class DialectOptionTest {
    private String out;
    private String err;

    private int main(String... args) {
        StringWriter o = new StringWriter();
        StringWriter e = new StringWriter();
        int code = Main.execute(args, new ByteArrayInputStream(new byte[0]), new PrintWriter(o), new PrintWriter(e));
        out = o.toString();
        err = e.toString();
        return code;
    }

    @Test
    void runDrivesTheFakeEpuckWithABundledController() throws Exception {
        try (OnSocket<FakeEpuck> robot = OnSocket.start((in, o) -> new FakeEpuck(in, o).start())) {
            assertEquals(0, main("run", "--port", robot.url(), "--dialect", "epuck", "--controller", "Braitenberg",
                    "--seconds", "1.5", "--max-speed", "200"), out + err);
            assertTrue(out.contains("robot answers: Version 1.1.3 September 2006 (e-puck)"), out);
            List<String> got = robot.robot().received();
            assertTrue(got.contains("D,6,6") && got.contains("Q"), "cruising, polled with Q: " + got.subList(0, 12));
            assertEquals("D,0,0", robot.robot().lastReceived());
        }
    }

    @Test
    void checkRunsTheEpucksCommands() throws Exception {
        try (OnSocket<FakeEpuck> robot = OnSocket.start((in, o) -> new FakeEpuck(in, o).start())) {
            assertEquals(0, main("check", "--port", robot.url(), "--dialect", "epuck"), out + err);
            assertTrue(out.contains("11 of 11 commands answered"), out);
            assertTrue(robot.robot().received().stream().noneMatch(l -> l.startsWith("T") || l.startsWith("H")),
                    "no Khepera or turret letter: " + robot.robot().received());
        }
    }

    @Test
    void wrongDialectsAndSettingsAreRefused() {
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--dialect", "thymio"));
        assertTrue(err.contains("dialect 'thymio' is not known; give one of khepera1, khepera2, epuck"), err);
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--max-speed", "200"));
        assertTrue(err.contains("--max-speed 200 is above the Khepera I's 127 (--dialect khepera1); give 0..127"), err);
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--dialect", "epuck",
                "--gripper"));
        assertTrue(err.contains("--gripper: the e-puck (--dialect epuck) takes no turret; leave --gripper out"), err);
    }
}
