package org.kheperasim.sim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.robot.WallReading;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code khepera-sim calibration-report}: the text gives each sensor's held-out error, the PNG a
 * panel per sensor; on a table made from a known smooth response the held-out error is small, on one
 * whose held-out blocks were changed it shows there.
 */
class CalibrationReportTest {

    /** A sampled wall from a smooth response; {@code bump} is added to every held-out block's readings. */
    static String table(int bump) {
        StringBuilder sb = new StringBuilder("8 24 12 5 3\n");
        for (int t = 0; t < 12; t++) {
            sb.append("TURN ").append(t).append('\n');
            for (int k = 0; k < 24; k++) {
                for (int i = 0; i < 8; i++) {
                    double d = WallReading.beamDistanceMm(RobotTypes.KHEPERA1, i, 5 + 3 * t, k * 15, 0);
                    double off = StrictMath.abs(Math.IEEEremainder(-k * 15 - RobotTypes.KHEPERA1.sensor(i).headingDeg(), 360));
                    double v = d > 45 || off > 60 ? 0 : 1023 * (1 - d / 45) * (1 - d / 45) * StrictMath.cos(StrictMath.toRadians(off * 1.4));
                    if (FitReport.heldOut(t) && v > 0) {
                        v += bump;
                    }
                    sb.append(String.format(Locale.ROOT, "%.6f ", StrictMath.rint(StrictMath.max(0, StrictMath.min(1023, v))) / 1023));
                }
                sb.append('\n');
            }
        }
        return sb.append("END\n").toString();
    }

    @Test
    void writesTheErrorsAsTextAndAPanelPerSensor(@TempDir Path dir) throws Exception {
        Path sample = dir.resolve("smooth.sample");
        Files.writeString(sample, table(0));
        Cli.Printed p = Cli.main("calibration-report", sample.toString());
        assertEquals(0, p.code(), p.err());
        String text = Files.readString(dir.resolve("smooth-fit.txt"));
        assertTrue(text.contains("LEFT_90") && text.contains("BACK_LEFT"), text);
        BufferedImage img = ImageIO.read(dir.resolve("smooth-fit.png").toFile());
        assertEquals(4 * 320, img.getWidth());
        assertEquals(2 * 240, img.getHeight());
        FitReport smooth = FitReport.of(org.kheperasim.sim.engine.robot.SampleTable.read(sample), RobotTypes.KHEPERA1);
        for (FitReport.Errors e : smooth.sensors().subList(0, 6)) {
            assertTrue(e.rms() < 51, "a smooth response's held-out rms " + e.rms() + "\n" + text);
        }
        Path bumped = dir.resolve("bumped.sample");
        Files.writeString(bumped, table(150));
        FitReport b = FitReport.of(org.kheperasim.sim.engine.robot.SampleTable.read(bumped), RobotTypes.KHEPERA1);
        for (int i = 0; i < 6; i++) {
            assertTrue(b.sensors().get(i).rms() > smooth.sensors().get(i).rms() + 40,
                    "sensor " + i + ": held-out blocks raised by 150 show in the held-out error: " + b.text());
        }
    }

    @Test
    void aMissingFileIsOneLineNamingIt() {
        Cli.Printed p = Cli.main("calibration-report", "/no/such.calibration");
        assertEquals(2, p.code());
        assertTrue(p.err().contains("/no/such.calibration") && p.err().strip().lines().count() == 1, p.err());
    }
}
