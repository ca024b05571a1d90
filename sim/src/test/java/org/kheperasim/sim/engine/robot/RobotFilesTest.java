package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Robot files: the bundled ones read, a written file re-saves byte for byte, every wrong field is refused by line. */
class RobotFilesTest {

    @ParameterizedTest
    @ValueSource(strings = {"khepera1", "khepera2", "epuck"})
    void aSavedFileReadsBackToTheSameRobotAndResavesByteForByte(String name) {
        RobotType t = RobotTypes.named(name);
        String saved = RobotFileWriter.write(t);
        RobotType again = RobotFileReader.parse("saved.yaml", saved);
        assertEquals(t, again);
        assertEquals(saved, RobotFileWriter.write(again));
    }

    @Test
    void theKhepera1FileHoldsThePapersRobot() {
        RobotType k = RobotTypes.KHEPERA1;
        assertEquals(27.5, k.body().radiusMm());
        assertEquals(53.0, k.drive().wheelBaseMm());
        assertEquals(8.0, k.drive().mmPerSecondPerUnit());
        assertEquals(127, k.drive().maxSpeed());
        assertEquals(10_000_000L, k.drive().motorPeriodNanos());
        assertEquals(8, k.sensorCount());
        assertEquals(26.5, k.sensorReachMm());
        assertEquals("khepera1", k.dialect());
        assertEquals(600.0, k.proximity().response().along(0).valueAt(20));
    }

    @Test
    void theEpuckListsItsSensorsLeftToRightWithItsOwnChannels() {
        RobotType e = RobotTypes.named("epuck");
        assertEquals(35.0, e.body().radiusMm());
        assertEquals(1000, e.drive().maxSpeed());
        assertEquals("ps7", e.sensor(2).name());
        assertEquals(7, e.sensor(2).channel());
        assertEquals(0, e.sensor(3).channel());
        assertTrue(e.sensor(0).headingDeg() > 0 && e.sensor(5).headingDeg() < 0, "left first, right after");
    }

    @Test
    void aTableInterpolatesOverDistanceAndAngle() {
        String text = RobotFileWriter.write(RobotTypes.KHEPERA1).replace(
                "  response: curve\n  angles: [0, 12, 24]\n  weights: [1, 0.85, 0.5]\n"
                        + "  distances: [0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60]\n"
                        + "  values: [1023, 985, 880, 745, 600, 455, 325, 215, 130, 70, 30, 10, 0]\n",
                "  response: table\n  angles: [0, 20]\n  distances: [0, 40]\n  values:\n    - [1000, 0]\n    - [500, 0]\n");
        RobotType t = RobotFileReader.parse("table.yaml", text);
        Response r = t.proximity().response();
        assertEquals(500.0, r.valueAt(20, 0), 1e-9);
        assertEquals(375.0, r.valueAt(20, 10), 1e-9);
        assertEquals(375.0, r.valueAt(20, -10), 1e-9);
        assertEquals(0.0, r.valueAt(20, 30), 1e-9);
        assertEquals(text, RobotFileWriter.write(RobotFileReader.parse("again.yaml", RobotFileWriter.write(t))));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "  radius: 27.5|  radius: 2|robot.yaml:8: radius 2 is out of range; use 5 to 500 mm",
        "  radius: 27.5|  radius: big|robot.yaml:8: radius 'big' is not a number; write digits, e.g. 27.5",
        "  radius: 27.5|  radus: 27.5|robot.yaml:8: 'radus' is not a key of 'footprint'; use radius, type",
        "  max_speed: 127|  max_speed: 12.5|robot.yaml:12: max_speed 12.5 is not a whole number; use a whole number of speed units",
        "    channel: 3|    channel: 2|robot.yaml:29: channel 2 is used twice; number the sensors' channels 0 to 7, each once",
        "    origin: [25, 6, 0]|    origin: [25, 6]|robot.yaml:27: origin has 2 values; give 3",
        "    origin: [25, 6, 0]|    origin: [80, 6, 0]|robot.yaml:27: origin [80, 6] is 80.2 mm from the centre, beyond the body (radius 27.5 mm); mount the sensor on the body",
        "  response: curve|  response: spline|robot.yaml:44: response 'spline' is not known; use curve or table",
        "dialect: khepera1|dialect: |robot.yaml:4: 'dialect' has no value; write 'dialect: <value>'",
        "turrets: [gripper, vision]|turrets: [laser]|robot.yaml:5: turret 'laser' is not known; use gripper, vision, or [] for none",
    })
    void everyWrongFieldIsRefusedWithItsLineValueAndFix(String from, String to, String message) {
        String text = RobotFileWriter.write(RobotTypes.KHEPERA1);
        assertTrue(text.contains(from + "\n"), from);
        String broken = text.replaceFirst(java.util.regex.Pattern.quote(from + "\n"), java.util.regex.Matcher.quoteReplacement(to + "\n"));
        RobotFileException e = assertThrows(RobotFileException.class, () -> RobotFileReader.parse("robot.yaml", broken));
        assertEquals(message, e.getMessage());
    }

    @Test
    void aMissingSectionIsNamed() {
        String text = RobotFileWriter.write(RobotTypes.KHEPERA1);
        String noLight = text.substring(0, text.indexOf("light:\n"));
        RobotFileException e = assertThrows(RobotFileException.class, () -> RobotFileReader.parse("r.yaml", noLight));
        assertEquals("r.yaml: 'light' is missing; add 'light: ...' (docs/robot-files.md lists every field)", e.getMessage());
    }

    @Test
    void aFileOnDiskIsFoundByPathAndAMissingOneIsNamed(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("tri.yaml");
        Files.writeString(f, RobotFileWriter.write(RobotTypes.KHEPERA1).replace("name: khepera1", "name: tri"));
        assertEquals("tri", RobotTypes.resolve("tri.yaml", dir).name());
        assertEquals("epuck", RobotTypes.resolve("epuck", dir).name());
        RobotFileException e = assertThrows(RobotFileException.class, () -> RobotTypes.resolve("nope.yaml", dir));
        assertTrue(e.getMessage().endsWith("nope.yaml: no such robot file; give a bundled robot (khepera1, khepera2, epuck, wsu)"
                + " or the path of a robot file"), e.getMessage());
    }
}
