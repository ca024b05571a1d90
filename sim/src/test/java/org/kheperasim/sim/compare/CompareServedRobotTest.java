package org.kheperasim.sim.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.cli.Main;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.serve.ProtocolServer;
import org.kheperasim.sim.serve.ServedArena;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code compare} on a real run's recording where the "real robot" is the simulator served over the
 * protocol, with other settings standing in for a robot that is not the model: its right wheel runs
 * at 0.9 of the commanded speed and its sensor 2 is dead. {@code khepera-link run --record} drives it
 * with the bundled Braitenberg in the open lab (it drives straight: nothing in range), and
 * {@code compare} replays the same controller from the same start with the default robot (the
 * recording keeps every line sent and received, with its time). The known
 * answers: sensor 2 differs by the offset the live sensor reads (15 counts) and no other sensor
 * differs; the paths part at the time the arcs say, about 3.6 s at 30 mm (48 mm/s straight against
 * 45.6 mm/s turning 5.2 degrees a second).
 */
@Tag("timing")
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CompareServedRobotTest {
    @TempDir
    Path dir;

    @Test
    void aServedRobotWithASlowWheelAndADeadSensorDivergesAsItWasGiven() throws Exception {
        Settings notTheModel = Settings.defaults().withNoise(0).with("motor.right.calibration", "0.9")
                .with("prox.2.dead", "true");
        Path rec = dir.resolve("served.rec");
        try (ServedArena world = new ServedArena(ArenaFormat.resolve("lab"), notTheModel, 1, 1)) {
            ProtocolServer server = ProtocolServer.start(world.robots().get(0), 0);
            try {
                StringWriter out = new StringWriter();
                int code = Main.execute(new String[] {"run", "--port", "tcp://127.0.0.1:" + server.port(), "--controller",
                    "Braitenberg", "--seconds", "6", "--record", rec.toString()}, new ByteArrayInputStream(new byte[0]),
                        new PrintWriter(out, true), new PrintWriter(out, true));
                assertEquals(0, code, out.toString());
            } finally {
                server.close();
            }
        }
        // The recording keeps every line sent and received, with its time, beside the samples.
        java.util.List<String> lines = Files.readAllLines(rec);
        assertTrue(lines.get(0).startsWith("# khepera-link recording v2"), lines.get(0));
        assertTrue(lines.stream().anyMatch(l -> l.matches("> [0-9.]+ D,6,6")), "Braitenberg's cruise command is kept");
        assertTrue(lines.stream().anyMatch(l -> l.matches("< [0-9.]+ d")), "and the robot's reply");
        long polls = lines.stream().filter(l -> l.matches("> [0-9.]+ N")).count();
        long samples = lines.stream().filter(l -> !l.startsWith("#") && !l.startsWith(">") && !l.startsWith("<")).count();
        assertTrue(polls >= samples && samples > 20, polls + " proximity polls for " + samples + " samples");
        Cli.Printed p = Cli.main("compare", rec.toString(), "--arena", "lab", "--controller", "Braitenberg", "--noise", "0",
                "--threshold-mm", "30", "--out", dir.toString());
        assertEquals(0, p.code(), p.out() + p.err());
        Divergence d = Divergence.of(Track.read(rec), SimulatedRun.run(ArenaFormat.resolve("lab"), null, null, "Braitenberg",
                Settings.defaults().withNoise(0), 1, Track.read(rec).seconds() + 0.05, 10), 0.08, 53, 30);
        for (int i = 0; i < 8; i++) {
            if (i == 2) {
                assertEquals(15, d.sensorRms()[i], 1, "the dead sensor against a live one on open floor");
            } else {
                assertTrue(d.sensorRms()[i] < 1, "sensor " + i + " differs by " + d.sensorRms()[i] + ": " + p.out());
            }
        }
        System.out.println(p.out());
        // compare dead-reckons both paths from the recording's first sample on: the arcs part from there. On a
        // busy machine that first poll can come a second or more after the robot set off.
        double expected = Track.read(rec).samples().get(0).seconds() + parting(30);
        assertEquals(expected, d.partedAt(), 0.4, "the paths part when the arcs say (" + expected + " s): " + p.out());
        assertTrue(p.out().contains(String.format(java.util.Locale.ROOT, "first more than 30.0 mm apart at")), p.out());
        assertTrue(Files.size(dir.resolve("served-compare.png")) > 0);
        // The page plays both runs side by side: two robots, the real one and its simulation.
        String page = Files.readString(dir.resolve("served-compare.html"));
        assertTrue(page.contains("robot 1 is the real robot, robot 2 its simulation"), "the page says which is which");
        assertTrue(Files.readString(dir.resolve("served-compare.json")).contains("\"sensorRms\":["));
    }

    /** @return when a robot at 48 and 43.2 mm/s is {@code mm} from one driving straight at 48 mm/s, s */
    private static double parting(double mm) {
        double vc = (48 + 43.2) / 2;
        double w = (43.2 - 48) / 53;
        for (double t = 0; t < 20; t += 0.001) {
            double x = vc / w * StrictMath.sin(w * t);
            double y = vc / w * (1 - StrictMath.cos(w * t));
            if (StrictMath.hypot(48 * t - x, y) > mm) {
                return t;
            }
        }
        return Double.NaN;
    }
}
