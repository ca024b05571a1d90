package org.kheperasim.sim.calibration;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotFileReader;
import org.kheperasim.sim.engine.robot.RobotFileWriter;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.testfixtures.Cli;

/**
 * A calibration ({@code khepera-link calibrate}'s {@code .calibration} file) is a robot file: the
 * robot it measured. {@code --robot-file} and an arena's robot line take it; saved from the type (as
 * the window's robot editor saves), it is a robot file that reads back to the same bytes and runs the
 * same robot; the measured robot draws no per-robot spread and brings its sensors' gains and wheels'
 * calibrations.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CalibrationIsARobotFileTest {
    @TempDir
    Path dir;

    @Test
    void aCalibrationRunsWhereverARobotFileDoes() throws Exception {
        // The calibration and its wall samples, copied beside this test's arena.
        Path made = CalibrateAgainstFakeTest.shared().calibration();
        Path cal = Files.copy(made, dir.resolve(made.getFileName()));
        Files.copy(made.resolveSibling("lab3-2026-12-02-wall.sample"), dir.resolve("lab3-2026-12-02-wall.sample"));
        RobotType t = RobotTypes.load(cal);
        assertEquals("lab3", t.measured().robot());
        assertEquals("khepera1", t.name(), "a calibration is its base robot, measured");

        // The measured robot: its own gains and wheels, no drawn spread (a kind of robot draws one).
        RobotModel m = RobotModel.of(Settings.defaults(), t);
        assertEquals(0, m.proximity().gainSpread());
        assertEquals(0, m.proximity().offsetSpread());
        assertEquals(0, m.motors().spread());
        assertTrue(RobotModel.of(Settings.defaults(), RobotTypes.KHEPERA1).proximity().gainSpread() > 0);
        double[] gains = new double[8];
        for (int i = 0; i < 8; i++) {
            gains[i] = t.measured().gain(i);
        }
        assertArrayEquals(gains, m.proximity().gain());
        assertEquals(t.measured().rightCalibration() / t.measured().leftCalibration(),
                m.motors().calibrationRight() / m.motors().calibrationLeft(), 1e-12);

        // Saved as a robot file it reads back to the same robot, and writes the same bytes again.
        String text = RobotFileWriter.write(t);
        assertTrue(text.contains("measured:\n  robot: lab3\n  date: 2026-12-02\n  gains: ["), text);
        RobotType back = RobotFileReader.parse("lab3.yaml", text);
        assertEquals(text, RobotFileWriter.write(back));
        assertEquals(t.measured(), back.measured());
        Path saved = dir.resolve("lab3.yaml");
        Files.writeString(saved, text);

        // --robot-file takes either; both run the same robot, step for step; the default Khepera runs otherwise.
        List<String> fromCalibration = run("--robot-file", cal.toString());
        List<String> fromSaved = run("--robot-file", saved.toString());
        List<String> plain = run("--robot-file", "khepera1");
        assertTrue(fromCalibration.contains("# robot-types 0=khepera1/lab3@2026-12-02"), header(fromCalibration));
        assertEquals(body(fromCalibration), body(fromSaved));
        assertNotEquals(body(fromCalibration), body(plain), "the calibration changed nothing");

        // An arena's robot line names it, by a path from the arena's folder.
        Path arena = dir.resolve("measured.arena");
        Files.writeString(arena, "khepera-arena 1\nname measured\nsize 1219.2 1219.2\nwall 0 600 800 600 8\n"
                + "robot 300 300 90 " + cal.getFileName() + "\nrobot 900 300 90\n");
        Path trace = dir.resolve("arena.trace");
        Cli.Printed p = Cli.main("run", "--arena", arena.toString(), "--controller", "Braitenberg", "--seconds", "5",
                "--seed", "3", "--trace", trace.toString());
        assertEquals(0, p.code(), p.out() + p.err());
        assertTrue(Files.readAllLines(trace).contains("# robot-types 0=khepera1/lab3@2026-12-02 1=khepera1"),
                header(Files.readAllLines(trace)));
        assertNull(RobotTypes.KHEPERA1.measured());
    }

    private List<String> run(String... robot) throws Exception {
        Path trace = Files.createTempFile(dir, "run", ".trace");
        String[] args = {"run", "--arena", "lab", robot[0], robot[1], "--controller", "Braitenberg", "--seconds", "20",
            "--seed", "4", "--trace", trace.toString()};
        Cli.Printed p = Cli.main(args);
        assertEquals(0, p.code(), p.out() + p.err());
        return Files.readAllLines(trace);
    }

    private static List<String> body(List<String> trace) {
        return trace.stream().filter(l -> !l.startsWith("#")).toList();
    }

    private static String header(List<String> trace) {
        return String.join("\n", trace.stream().filter(l -> l.startsWith("#")).toList());
    }
}
