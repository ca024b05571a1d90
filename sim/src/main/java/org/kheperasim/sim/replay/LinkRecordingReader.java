package org.kheperasim.sim.replay;

import java.util.List;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.trace.TraceFormatException;

/**
 * Reads a robot-link recording of a real robot ({@code khepera-link run --record FILE}: one line
 * per poll cycle with the time, 8 proximity, 8 light values, both encoders and the speeds sent).
 * The real robot has no pose sensor, so the pose is dead-reckoned from the encoders with the robot's
 * own drive numbers (its type's or its calibration's mm per pulse and wheel base; a recording alone is
 * read as a Khepera I's), starting at {@code start}.
 */
final class LinkRecordingReader {
    /** The recording's first line starts with this. */
    static final String MAGIC = "# khepera-link recording";
    private static final int COLUMNS = 21;

    private LinkRecordingReader() {
    }

    /**
     * @param text the recording
     * @param source how errors name it
     * @param x start x, mm
     * @param y start y, mm
     * @param headingDeg start heading, degrees
     * @param notes where to say what was cut short
     * @return the robot's series
     * @throws TraceFormatException naming {@code source:line}
     */
    static RobotSeries read(String text, String source, double x, double y, double headingDeg, List<String> notes) {
        RobotType.Drive d = RobotTypes.KHEPERA1.drive();
        return read(text, source, x, y, headingDeg, d.mmPerPulse(), d.wheelBaseMm(), notes);
    }

    /**
     * As {@link #read(String, String, double, double, double, List)}, dead-reckoned with these wheels.
     *
     * @param mmPerPulse the robot's wheel travel per encoder pulse, mm
     * @param wheelBaseMm its wheel base, mm
     */
    static RobotSeries read(String text, String source, double x, double y, double headingDeg, double mmPerPulse,
            double wheelBaseMm, List<String> notes) {
        String[] lines = text.split("\n", -1);
        int end = lines.length - 1;
        if (!text.endsWith("\n")) {
            notes.add(source + " ends in the middle of a line (the run was cut); replaying the whole lines");
        }
        RobotSeries series = new RobotSeries();
        int[] ch = new int[RobotSeries.CHANNELS];
        double heading = StrictMath.toRadians(headingDeg);
        long prevL = 0;
        long prevR = 0;
        boolean first = true;
        for (int i = 0; i < end; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#") || line.startsWith(">") || line.startsWith("<")) {
                // v2 recordings keep every line sent (>) and received (<) too: the replay plays the samples
                continue;
            }
            String[] f = line.split(" +");
            if (f.length != COLUMNS) {
                throw new TraceFormatException(source, i + 1,
                        "a recording line has " + COLUMNS + " columns (t_s, prox0..7,"
                        + " light0..7, posL posR speedL speedR); this one has " + f.length);
            }
            try {
                double t = Double.parseDouble(f[0]);
                for (int c = 0; c < 16; c++) {
                    ch[c] = Integer.parseInt(f[1 + c]);
                }
                long posL = Long.parseLong(f[17]);
                long posR = Long.parseLong(f[18]);
                ch[RobotSeries.ENCODER] = (int) posL;
                ch[RobotSeries.ENCODER + 1] = (int) posR;
                ch[RobotSeries.SPEED] = Integer.parseInt(f[19]);
                ch[RobotSeries.SPEED + 1] = Integer.parseInt(f[20]);
                if (!first) {
                    double dl = (posL - prevL) * mmPerPulse;
                    double dr = (posR - prevR) * mmPerPulse;
                    double turn = (dr - dl) / wheelBaseMm;
                    double mid = heading + turn / 2;
                    x += (dl + dr) / 2 * StrictMath.cos(mid);
                    y += (dl + dr) / 2 * StrictMath.sin(mid);
                    heading += turn;
                }
                first = false;
                prevL = posL;
                prevR = posR;
                series.add(t, x, y, StrictMath.toDegrees(heading), ch, Contact.NONE, GripperTurret.ARM_UP,
                        GripperState.OPEN,
                        false, -1);
            } catch (IllegalArgumentException e) {
                throw new TraceFormatException(source, i + 1, "cannot read this line: " + e.getMessage()
                        + "; is the file a robot-link recording?");
            }
        }
        if (series.size() == 0) {
            throw new TraceFormatException(source, 0,
                    "the recording has no sample (the run ended before its first poll)");
        }
        return series;
    }
}
