package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.link.io.Links;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.robot.PollBench;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * One link timing model, and it holds on the wire: the poll rate robot-link measures against the
 * protocol server (which paces each reply by its real length) is never faster than the rate a
 * controller sees in the simulator, by more than the 10 % the model allows, at 9600, 38400 and
 * 115200 baud; and it reaches at least a quarter of it even with every core busy. Both robots stand
 * at the same spot of the same arena, so their replies carry numbers of the same lengths. On a
 * quiet machine the two agree within a few per cent (the figures are printed; docs/robot-link.md
 * quotes them).
 *
 * <p>The served rate is a wall-clock measurement: load can only make it lower, so it is the best of
 * up to three windows of about 40 cycles, stopping at the first that agrees within 10 %. Tagged
 * {@code timing}: {@code .ci/run} runs it again with both cores busy (held to 10 % both ways, it
 * took up to ten windows, 20 s, in a loaded build, and a saturated machine could fail it).
 *
 * <p>Tagged {@code realtime} too: the rate it checks is the wall clock's, which holds on an idle machine and
 * beside two busy loops but not at load 30 on 2 cores (it failed 2 of 5 whole-suite runs there), so the
 * default {@code mvn -B verify} leaves it out and {@code .ci/run}'s busy pass runs it
 * ({@code kheperasim.excludedGroups} in the parent pom).
 */
@Tag("timing")
@Tag("realtime")
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PollRateAgreementTest {
    private static final String ARENA = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 600 600 90\n"
            + "wall 0 4 1219.2 4 8\nwall 0 1215.2 1219.2 1215.2 8\nwall 4 0 4 1219.2 8\nwall 1215.2 0 1215.2 1219.2 8\n";

    /**
     * Poll cycles per simulated second the simulator's link runs: its proximity replies. (Not the
     * changes of the values a controller sees: a reply carries the robot's latest 20 ms scan, so at
     * 115200 baud two replies often carry the same one.)
     */
    private static double simulatedRate(Settings settings) {
        Engine engine = new Engine(new World(ArenaFormat.parse(ARENA, "t.arena")), 5);
        SimRobot robot = engine.addRobot("r", new Pose(600, 600, 90), settings);
        long end = 20_000_000_000L;
        long before = robot.controls().pollCycles();
        engine.runUntil(end);
        return (robot.controls().pollCycles() - before) / (end / 1e9);
    }

    /**
     * Load can only slow the loop down: the best of up to three windows of about 40 cycles; it
     * stops as soon as one agrees with {@code expected} within 10 %.
     */
    private static double servedRate(Settings settings, int baud, double expected) throws Exception {
        double best = 0;
        ServedRobot robot = new ServedRobot(ArenaFormat.parse(ARENA, "t.arena"), settings, 5, 1);
        try (ProtocolServer server = ProtocolServer.start(robot, 0);
                Session session = new Session(Links.open(SerialSettings.khepera("tcp://127.0.0.1:" + server.port(), baud)),
                        LinkTiming.atBaud(baud), Session.Options.defaults())) {
            session.open();
            long window = StrictMath.max(400, (long) (40_000 / expected));
            for (int attempt = 0; attempt < 3 && StrictMath.abs(best / expected - 1) > 0.10; attempt++) {
                best = StrictMath.max(best, PollBench.measure(session, baud, window).rateHz());
            }
        } finally {
            robot.close();
        }
        return best;
    }

    @ParameterizedTest(name = "{0} baud")
    @ValueSource(ints = {9600, 38400, 115200})
    void theSimulatorsPollRateIsTheWiresPollRate(int baud) throws Exception {
        Settings settings = Settings.defaults().with("link.baud", Integer.toString(baud));
        double sim = simulatedRate(settings);
        double served = servedRate(settings, baud, sim);
        double longest = 1e9 / LinkTiming.atBaud(baud).pollCycleNanos();
        System.out.printf(Locale.ROOT, "%6d baud: simulator %.1f cycles/s, robot-link against serve %.1f/s"
                + " (every reply at its longest: %.1f/s)%n", baud, sim, served, longest);
        assertTrue(sim > longest * 1.2, "replies as long as their numbers poll faster than the longest replies: "
                + sim + " vs " + longest);
        assertTrue(served <= sim * 1.10, "the server never replies faster than the wire allows: served " + served
                + "/s vs simulated " + sim + "/s");
        assertTrue(served >= sim * 0.25, "at least a quarter of the simulated rate, even on a busy machine: served " + served
                + "/s vs simulated " + sim + "/s");
    }
}
