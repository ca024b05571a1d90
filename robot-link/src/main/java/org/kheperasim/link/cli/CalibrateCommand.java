package org.kheperasim.link.cli;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.kheperasim.link.calibrate.Answers;
import org.kheperasim.link.calibrate.CalibrationRun;
import org.kheperasim.link.calibrate.DriftCheck;
import org.kheperasim.link.calibrate.RobotBase;
import org.kheperasim.link.session.Session;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code calibrate}: measure one real robot, guided on the console (docs/calibration.md). */
@picocli.CommandLine.Command(name = "calibrate", mixinStandardHelpOptions = true,
        description = "Measure the robot's wheels,"
        + " its sensors against a white wall at distances and headings, and a lamp, guided step by step; write the raw"
        + " samples and a dated calibration file. --check re-measures a few points against a calibration.")
final class CalibrateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    Connection connection;

    @Option(names = "--robot", defaultValue = "khepera", paramLabel = "NAME",
            description = "The robot's name (its label). Default: ${DEFAULT-VALUE}.")
    String robot;

    @Option(names = "--out", defaultValue = ".", paramLabel = "DIR",
            description = "Where the files go. Default: the current folder.")
    Path out;

    @Option(names = "--date", paramLabel = "YYYY-MM-DD", description = "The calibration's date. Default: today (UTC).")
    String date;

    @Option(names = "--non-interactive", description = "Ask nobody: every question takes its --answer, or its default.")
    boolean nonInteractive;

    @Option(names = "--answer", paramLabel = "KEY=VALUE",
            description = "The answer to a question (its key is shown with it).")
    Map<String, String> given = new LinkedHashMap<>();

    @Option(names = "--readings", defaultValue = "20", paramLabel = "N",
            description = "Readings per sensor per point. Default: ${DEFAULT-VALUE}.")
    int readings;

    @Option(names = "--scan-ms", defaultValue = "20", paramLabel = "MS",
            description = "Time between readings, ms. Default: ${DEFAULT-VALUE} (the robot's scan).")
    long scanMillis;

    @Option(names = "--check", paramLabel = "FILE",
            description = "Re-measure a few wall points and compare them with this calibration.")
    Path check;

    @Option(names = "--threshold", defaultValue = "10", paramLabel = "PERCENT",
            description = "--check: the drift that fails, %%. Default: ${DEFAULT-VALUE}.")
    double thresholdPercent;

    @Override
    public Integer call() throws Exception {
        PrintWriter o = spec.commandLine().getOut();
        if (readings < 1 || readings > 1000 || scanMillis < 0 || scanMillis > 10_000) {
            throw new IllegalArgumentException("--readings " + readings + " / --scan-ms " + scanMillis
                    + ": give 1..1000 readings and 0..10000 ms");
        }
        if (!robot.matches("[A-Za-z0-9_.-]+")) {
            throw new IllegalArgumentException("--robot " + robot + ": use letters, digits, '.', '_' and '-' only");
        }
        String day = date != null ? date : LocalDate.now(ZoneOffset.UTC).toString();
        if (!day.matches("\\d{4}-\\d{2}-\\d{2}")) {
            throw new IllegalArgumentException("--date " + day + ": write it as YYYY-MM-DD");
        }
        BufferedReader in = nonInteractive ? null
                : new BufferedReader(new InputStreamReader(Main.in, StandardCharsets.UTF_8));
        Answers answers = new Answers(o, in, given, k -> { });
        try (Session session = connection.open(o)) {
            session.open();
            RobotBase base = RobotBase.of(session.dialect());
            if (check != null) {
                return DriftCheck.drifted(session, answers, o, check, readings, scanMillis,
                        thresholdPercent / 100) ? 1 : 0;
            }
            CalibrationRun.Plan p = CalibrationRun.Plan.standard();
            CalibrationRun run = new CalibrationRun(session, answers, o,
                    new CalibrationRun.Plan(readings, scanMillis, p.blocks(), p.headings(), p.runPulses(),
                            base.turnPulses()), base);
            Path file = run.run(robot, day).write(out);
            o.println("wrote " + file + " (and its -wall.sample and -samples.csv beside it)");
            o.flush();
            return 0;
        }
    }
}
