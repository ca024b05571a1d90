package org.kheperasim.sim.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.compare.Divergence;
import org.kheperasim.sim.compare.PathPlot;
import org.kheperasim.sim.compare.SimulatedRun;
import org.kheperasim.sim.compare.Track;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotType;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code compare}: a real run recorded by robot-link against the same controller run in the simulator. */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = "Replay a real run's controller from the same start"
        + " in the simulator (with the robot's calibration) and report where they diverge: RMS per"
        + " sensor, both odometry paths, the first moment they part; text, JSON, a PNG and a page that plays"
        + " both runs side by side.")
final class CompareCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "REAL-RECORDING", description = "The real run: a 'khepera-link run --record' file.")
    Path recording;

    @Option(names = "--arena", required = true, paramLabel = "ARENA",
            description = "The arena the real run took place in (a name or a file).")
    String arena;

    @Option(names = "--controller", required = true, paramLabel = "NAME",
            description = "The controller the real run ran.")
    String controller;

    @Option(names = "--start", paramLabel = "X,Y,HEADING", split = ",",
            description = "The robot's start, mm and degrees. Default: the arena's.")
    double[] start;

    @Option(names = "--calibration", paramLabel = "FILE",
            description = "The robot's calibration (khepera-link calibrate).")
    Path calibration;

    @Option(names = "--seed", defaultValue = "1", description = "The simulation's seed. Default: ${DEFAULT-VALUE}.")
    long seed;

    @Option(names = "--threshold-mm", defaultValue = "30", paramLabel = "MM",
            description = "How far apart the paths part. Default: ${DEFAULT-VALUE}.")
    double thresholdMm;

    @Option(names = "--out", paramLabel = "DIR", description = "Where the report goes. Default: beside the recording.")
    Path out;

    @picocli.CommandLine.Mixin
    SettingsOptions settingsOptions;

    @Override
    public Integer call() throws Exception {
        if (!Files.isRegularFile(recording)) {
            throw new IllegalArgumentException("recording " + recording
                    + " does not exist: give a 'khepera-link run --record' file");
        }
        if (start != null && start.length != 3) {
            throw new IllegalArgumentException("--start needs X,Y,HEADING (mm, mm, degrees), e.g. --start 200,300,90");
        }
        Track real = Track.read(recording);
        Arena a = ArenaFormat.resolve(arena);
        Settings s = settingsOptions.settings();
        RobotType type = null;
        if (calibration != null) {
            type = org.kheperasim.sim.engine.robot.RobotTypes.load(calibration);
        }
        RobotType used = type != null ? type : a.robotType(0);
        Track sim = SimulatedRun.run(a, start == null ? null : new Pose(start[0], start[1], start[2]), type,
                controller, s, seed,
                real.seconds() + 0.05, 10);
        double mmPerPulse = s.overrides().containsKey("encoder.mmPerPulse")
                ? s.number("encoder.mmPerPulse") : used.drive().mmPerPulse();
        Divergence d = Divergence.of(real, sim, mmPerPulse, used.drive().wheelBaseMm(), thresholdMm);
        Path dir = out != null ? out : recording.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        String stem = recording.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        org.kheperasim.sim.files.AtomicFiles.write(dir.resolve(stem + "-compare.txt"), d.text());
        org.kheperasim.sim.files.AtomicFiles.write(dir.resolve(stem + "-compare.json"), d.json());
        PathPlot.write(d, dir.resolve(stem + "-compare.png"));
        // The page that plays both runs side by side, from the same start in the arena.
        Pose from = start != null ? new Pose(start[0], start[1], start[2]) : a.robots().get(0);
        org.kheperasim.sim.replay.Replay both = org.kheperasim.sim.replay.ReplayFiles.sideBySide(
                Files.readString(recording), sim.text("the simulation of " + recording.getFileName()),
                recording.getFileName().toString(), a, from, mmPerPulse, used.drive().wheelBaseMm());
        org.kheperasim.sim.web.RunPage.write(both, org.kheperasim.sim.web.RunOutcome.none(),
                recording.getFileName() + " beside its simulation", dir.resolve(stem + "-compare.html"));
        spec.commandLine().getOut().print(d.text());
        spec.commandLine().getOut().println("wrote " + dir.resolve(stem + "-compare.txt")
                + ", .json, .png and .html (both runs side by side)");
        spec.commandLine().getOut().flush();
        return 0;
    }
}
