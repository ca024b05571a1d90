package org.kheperasim.sim.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.kheperasim.sim.calibration.FitPlot;
import org.kheperasim.sim.calibration.FitReport;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.robot.SampleTable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code calibration-report}: how well a calibration's (or a .sample file's) table fits, as text and a picture. */
@Command(name = "calibration-report", mixinStandardHelpOptions = true, description = "Fit a calibration's wall samples"
        + " (a .calibration file, or a .sample file) holding every third distance out, and write the per-sensor errors"
        + " as text and a PNG (samples, fitted table, held-out points).")
final class CalibrationReportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "A .calibration file (khepera-link calibrate) or a .sample file.")
    Path file;

    @Option(names = "--out", paramLabel = "DIR", description = "Where the report goes. Default: beside FILE.")
    Path out;

    @Override
    public Integer call() throws Exception {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("calibration " + file
                    + " does not exist: give a .calibration or .sample file");
        }
        Path sample = file;
        if (file.getFileName().toString().endsWith(".calibration")) {
            String wall = Files.readAllLines(file).stream().filter(l -> l.startsWith("wall ")).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("calibration " + file
                            + " names no wall file: add 'wall FILE.sample'"))
                    .substring(5).trim();
            sample = file.toAbsolutePath().getParent().resolve(wall);
        }
        FitReport report = FitReport.of(SampleTable.read(sample), RobotTypes.KHEPERA1);
        Path dir = out != null ? out : file.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        String stem = file.getFileName().toString().replaceFirst("\\.(calibration|sample)$", "");
        Path txt = dir.resolve(stem + "-fit.txt");
        Path png = dir.resolve(stem + "-fit.png");
        org.kheperasim.sim.files.AtomicFiles.write(txt, report.text());
        FitPlot.write(report, png);
        spec.commandLine().getOut().print(report.text());
        spec.commandLine().getOut().println("wrote " + txt + " and " + png);
        spec.commandLine().getOut().flush();
        return 0;
    }
}
