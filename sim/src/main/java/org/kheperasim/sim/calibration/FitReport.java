package org.kheperasim.sim.calibration;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.SampleFit;
import org.kheperasim.sim.engine.robot.SampleTable;

/**
 * How well a fitted table reproduces a sampled wall table: fitted on all blocks but every third
 * (1, 4, 7, ...), then, per sensor, the error at those held-out blocks and at the fitted ones.
 * {@link FitPlot} draws it.
 *
 * @param table the sampled readings
 * @param type the robot that took them
 * @param heldOutFit the fit without the held-out blocks (the errors are this fit's)
 * @param fullFit the fit on every block (what the simulator loads)
 * @param sensors per sensor: median and RMS held-out error, RMS fitted error, counts
 */
public record FitReport(SampleTable table, RobotType type, SampleFit.Result heldOutFit, SampleFit.Result fullFit,
        List<Errors> sensors) {

    /**
     * @param median median absolute error at the held-out blocks, counts
     * @param rms RMS error at the held-out blocks, counts
     * @param fittedRms RMS error at the blocks it was fitted on, counts
     * @param litMedian median absolute held-out error where the robot read more than 50, counts (NaN: none)
     */
    public record Errors(double median, double rms, double fittedRms, double litMedian) {
    }

    /** @param block a block @return whether the report holds it out */
    public static boolean heldOut(int block) {
        return block % 3 == 1;
    }

    /**
     * @param table sampled wall readings
     * @param type the robot that took them
     * @return the report
     */
    public static FitReport of(SampleTable table, RobotType type) {
        List<SampleFit.Sample> train = SampleFit.samples(table, t -> !heldOut(t));
        List<SampleFit.Sample> all = SampleFit.samples(table, t -> true);
        SampleFit.Result held = SampleFit.fit(type, train);
        SampleFit.Result full = SampleFit.fit(type, all);
        List<Errors> errors = new ArrayList<>();
        for (int i = 0; i < table.sensors(); i++) {
            List<Double> out = new ArrayList<>();
            List<Double> lit = new ArrayList<>();
            double in2 = 0;
            int inN = 0;
            for (int t = 0; t < table.blocks(); t++) {
                for (int k = 0; k < table.angles(); k++) {
                    double e = held.predict(type, i, table.gapMm(t), table.objectRightDeg(k)) - table.counts(t, k, i);
                    if (heldOut(t)) {
                        out.add(StrictMath.abs(e));
                        if (table.counts(t, k, i) > 50) {
                            lit.add(StrictMath.abs(e));
                        }
                    } else {
                        in2 += e * e;
                        inN++;
                    }
                }
            }
            double[] o = out.stream().mapToDouble(Double::doubleValue).toArray();
            double rms = StrictMath.sqrt(Arrays.stream(o).map(x -> x * x).sum() / StrictMath.max(1, o.length));
            errors.add(new Errors(median(o), rms, StrictMath.sqrt(in2 / StrictMath.max(1, inN)),
                    lit.isEmpty() ? Double.NaN : median(lit.stream().mapToDouble(Double::doubleValue).toArray())));
        }
        return new FitReport(table, type, held, full, List.copyOf(errors));
    }

    /** @return the report as text, a line per sensor */
    public String text() {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT,
                "fit of %s: %d sensors, %d headings, %d blocks (%.1f..%.1f mm); held out: blocks 1, 4, 7, ...%n",
                table.source(), table.sensors(), table.angles(), table.blocks(), table.gapMm(0),
                table.gapMm(table.blocks() - 1)));
        sb.append(String.format(Locale.ROOT,
                "loaded fit: offset %.1f counts, noise %.1f counts + %.1f %% of the signal%n",
                fullFit.offset(), fullFit.noiseAbs(), 100 * fullFit.noiseRel()));
        sb.append(String.format(Locale.ROOT, "%-12s %6s %10s %10s %14s %10s%n", "sensor", "gain",
                "held med", "held rms",
                "held med lit", "fit rms"));
        for (int i = 0; i < sensors.size(); i++) {
            Errors e = sensors.get(i);
            sb.append(String.format(Locale.ROOT, "%-12s %6.2f %10.1f %10.1f %14s %10.1f%n", type.sensor(i).name(),
                    fullFit.gains()[i],
                    e.median(), e.rms(),
                    Double.isNaN(e.litMedian()) ? "-" : String.format(Locale.ROOT, "%.1f", e.litMedian()),
                    e.fittedRms()));
        }
        sb.append("counts of 1023; 'lit': where the robot read more than 50; settings for the gains: ");
        for (int i = 0; i < fullFit.gains().length; i++) {
            sb.append(String.format(Locale.ROOT, "%sprox.%d.gain=%.3f", i == 0 ? "" : " ", i, fullFit.gains()[i]));
        }
        return sb.append('\n').toString();
    }

    static double median(double[] v) {
        if (v.length == 0) {
            return Double.NaN;
        }
        double[] a = v.clone();
        Arrays.sort(a);
        return a.length % 2 == 1 ? a[a.length / 2] : (a[a.length / 2 - 1] + a[a.length / 2]) / 2;
    }
}
