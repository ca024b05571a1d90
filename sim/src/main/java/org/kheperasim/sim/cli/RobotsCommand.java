package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code robots}: the bundled robots (and any robot files named), one line each. */
@Command(name = "robots", mixinStandardHelpOptions = true,
        description = {"List the bundled robots, and check the robot files named: name, sensors, size,"
                + " dialect, source.",
            "A robot is chosen with --robot-file FILE_OR_NAME, or in an arena's robot line: 'robot 300 300 0 epuck'."})
final class RobotsCommand implements Runnable {
    @Parameters(paramLabel = "FILE", arity = "0..*",
            description = "robot files to read and list too (a wrong one is refused by its line)")
    List<java.nio.file.Path> files = new ArrayList<>();

    @Override
    public void run() {
        System.out.println(String.format(Locale.ROOT, "%-10s %7s %8s %10s %7s  %s", "robot", "sensors", "diameter",
                "wheel base", "dialect", "source"));
        for (RobotType t : RobotTypes.all()) {
            System.out.println(line(t, "bundled"));
        }
        for (java.nio.file.Path f : files) {
            System.out.println(line(RobotTypes.load(f), f.toString()));
        }
    }

    private static String line(RobotType t, String where) {
        return String.format(Locale.ROOT, "%-10s %7d %5.1f mm %7.1f mm %7s  %s (%s)", t.name(), t.sensorCount(),
                2 * t.body().radiusMm(), t.drive().wheelBaseMm(), t.dialect(), t.source(), where);
    }
}
