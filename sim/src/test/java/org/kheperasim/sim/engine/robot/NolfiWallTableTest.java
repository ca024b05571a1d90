package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The Nolfi lab's sampled real Khepera ({@code ../shared/real-khepera/khepera-wall.sample}, GPL data
 * read in place, never copied): a table fitted on part of it reproduces the rest. Skipped where the
 * folder is absent; with {@code CI=true} its absence is a failure.
 */
class NolfiWallTableTest {

    static Path sampleFile(String name) {
        Path folder = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("../shared/real-khepera").normalize();
        if (!Files.isDirectory(folder)) {
            if ("true".equals(System.getenv("CI"))) {
                fail("the real Khepera sample files are not at " + folder.toAbsolutePath() + ", and CI=true requires"
                        + " these tests to run: check out shared/ beside the repository");
            }
            Assumptions.assumeTrue(false, "no real Khepera sample files at " + folder.toAbsolutePath());
        }
        return folder.resolve(name);
    }

    /** Held out: every third distance block (1, 4, ... 19) and the wall 30 to 60 degrees off ahead, either side. */
    static boolean heldOut(SampleTable s, int block, int angle) {
        double a = s.objectRightDeg(angle);
        return block % 3 == 1 || (a >= 30 && a <= 60) || (a >= 300 && a <= 330);
    }

    static List<SampleFit.Sample> samples(SampleTable s, boolean held) {
        List<SampleFit.Sample> out = new ArrayList<>();
        for (int t = 0; t < s.blocks(); t++) {
            for (int k = 0; k < s.angles(); k++) {
                if (heldOut(s, t, k) == held) {
                    for (int i = 0; i < s.sensors(); i++) {
                        out.add(new SampleFit.Sample(i, s.gapMm(t), s.objectRightDeg(k), s.counts(t, k, i)));
                    }
                }
            }
        }
        return out;
    }

    @Test
    void readsTheLayoutTheReadmeDecodes() throws IOException {
        SampleTable s = SampleTable.read(sampleFile("khepera-wall.sample"));
        assertEquals(8, s.sensors());
        assertEquals(180, s.angles());
        assertEquals(20, s.blocks());
        assertEquals(5, s.gapMm(0));
        assertEquals(43, s.gapMm(19));
        // The README's decoding: wall ahead, sensors 2 and 3 read (on average) 1023 up to 15 mm, 926 at 17,
        // 693 at 19, 467 at 21.
        assertEquals(2 * 1023, s.counts(5, 0, 2) + s.counts(5, 0, 3));
        assertEquals(2 * 926, s.counts(6, 0, 2) + s.counts(6, 0, 3));
        assertEquals(2 * 693, s.counts(7, 0, 2) + s.counts(7, 0, 3), 1);
        assertEquals(2 * 467, s.counts(8, 0, 2) + s.counts(8, 0, 3), 1);
        // Index 45 (90 degrees right) lights the right side, 135 the left.
        assertTrue(s.counts(0, 45, 5) > 900 && s.counts(0, 45, 0) < 20);
        assertTrue(s.counts(0, 135, 0) > 900 && s.counts(0, 135, 5) < 20);
    }

    @Test
    void aTableFittedOnTheRestReproducesTheHeldOutReadings() throws IOException {
        SampleTable s = SampleTable.read(sampleFile("khepera-wall.sample"));
        RobotType k1 = RobotTypes.KHEPERA1;
        SampleFit.Result fit = SampleFit.fit(k1, samples(s, false));
        List<SampleFit.Sample> held = samples(s, true);
        double[] err = new double[held.size()];
        List<Double> lit = new ArrayList<>();
        for (int p = 0; p < held.size(); p++) {
            SampleFit.Sample h = held.get(p);
            err[p] = StrictMath.abs(fit.predict(k1, h.sensor(), h.gapMm(), h.objectRightDeg()) - h.counts());
            if (h.counts() > 50) {
                lit.add(err[p]);
            }
        }
        double median = median(err);
        double medianLit = median(lit.stream().mapToDouble(Double::doubleValue).toArray());
        System.out.printf(Locale.ROOT, "held-out readings %d: median error %.1f counts, rms %.1f; of the %d lit (> 50): median %.1f%n",
                held.size(), median, rms(err), lit.size(), medianLit);
        System.out.printf(Locale.ROOT, "fit: offset %.1f noiseAbs %.1f noiseRel %.3f gains %s%n", fit.offset(), fit.noiseAbs(),
                fit.noiseRel(), Arrays.toString(Arrays.stream(fit.gains()).map(g -> StrictMath.rint(g * 100) / 100).toArray()));
        report(s, k1, "fitted (held-out only)", fit.table(), fit.gains(), fit.offset(), true);
        SampleFit.Result flat = SampleFit.fit(k1, samples(s, false), false);
        report(s, k1, "fitted, gains 1 (held-out)", flat.table(), flat.gains(), flat.offset(), true);
        report(s, k1, "fitted, all readings", fit.table(), fit.gains(), fit.offset(), false);
        report(s, k1, "khepera1", RobotTypes.profile("khepera1"), null, 15, false);
        report(s, k1, "khepera2", RobotTypes.profile("khepera2"), null, 15, false);
        assertTrue(median <= 0.05 * SampleTable.FULL_SCALE, "median held-out error " + median + " counts");
        assertTrue(medianLit <= 0.05 * SampleTable.FULL_SCALE * 2, "median held-out error of lit readings " + medianLit);
    }

    private static void report(SampleTable s, RobotType type, String name, Response r, double[] gains, double offset, boolean heldOnly) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%-24s RMS per sensor:", name));
        for (int i = 0; i < s.sensors(); i++) {
            double sum = 0;
            int n = 0;
            for (int t = 0; t < s.blocks(); t++) {
                for (int k = 0; k < s.angles(); k++) {
                    if (!heldOnly || heldOut(s, t, k)) {
                        double e = WallReading.reading(type, r, i, gains == null ? 1 : gains[i], offset, s.gapMm(t), s.objectRightDeg(k))
                                - s.counts(t, k, i);
                        sum += e * e;
                        n++;
                    }
                }
            }
            sb.append(String.format(Locale.ROOT, " %.0f", StrictMath.sqrt(sum / n)));
        }
        System.out.println(sb);
    }

    static double median(double[] v) {
        double[] a = v.clone();
        Arrays.sort(a);
        return a.length % 2 == 1 ? a[a.length / 2] : (a[a.length / 2 - 1] + a[a.length / 2]) / 2;
    }

    static double rms(double[] v) {
        double s = 0;
        for (double x : v) {
            s += x * x;
        }
        return StrictMath.sqrt(s / v.length);
    }
}
