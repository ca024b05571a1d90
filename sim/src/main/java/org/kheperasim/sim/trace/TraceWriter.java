package org.kheperasim.sim.trace;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;

/**
 * Writes a run as text: a header that says what produced it, then one line per robot per sample.
 * The same run always gives the same bytes, so traces diff cleanly and a hash identifies a run.
 *
 * <pre>
 * # khepera-trace 1
 * # seed 42
 * # arena maze sha256=…
 * # controller org.kheperasim.controllers.WallFollower
 * # settings defaults
 * # sample-ms 50
 * # columns t_s robot x_mm y_mm heading_deg speed_l speed_r enc_l enc_r contact prox0..prox7 light0..light7 arm …
 * # caps t_s cap id x_mm y_mm held_by
 * 0.000 0 150.000 150.000 90.000 0 0 0 0 NONE 15 14 … 180 OPEN 0 -1
 * 0.000 cap 0 300.000 420.000 -1
 * </pre>
 *
 * <p>The columns line (shortened above) ends {@code light0..light7 arm fingers object held_cap}.
 *
 * <p>A cap line is written at the first sample and then only when the cap has moved, been
 * picked up or put down since the last sample.
 *
 * <p>A robot whose controller reads its K213 vision turret gets a vision line when the image it
 * read has changed since the last sample: {@code # vision t_s robot taken_s p0 ... p63} (the time of
 * the sample, the robot, when the turret took the image, its 64 grey levels). It starts with
 * {@code #} so that readers of the robot and cap lines pass over it; a run that never reads the
 * turret writes none.
 *
 * <p>A run with a robot that is not a Khepera I names each robot's type in the header:
 * {@code # robot-types 0=khepera1 1=epuck} (a run of Khepera Is alone has no such line).
 */
public final class TraceWriter implements SnapshotListener, AutoCloseable {
    /** The trace format's version. */
    public static final int FORMAT_VERSION = 2;

    private final Writer out;
    private final MessageDigest digest;
    private final StringBuilder line = new StringBuilder(256);
    private String sha256;
    private double[] capX = new double[0];
    private double[] capY = new double[0];
    private int[] capHeld = new int[0];
    private boolean first = true;
    /** When each robot's last written image was taken, ns (-1: none yet). */
    private long[] visionTaken = new long[0];

    /**
     * @param out where the text goes (the writer is closed with this one)
     * @param header header fields in order, e.g. seed, arena, controller, settings, sample-ms
     */
    public TraceWriter(Writer out, Map<String, String> header) {
        this.out = out;
        try {
            this.digest = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this Java runtime has no SHA-256", e);
        }
        write("# khepera-trace " + FORMAT_VERSION + "\n");
        header.forEach((k, v) -> write("# " + k + " " + v + "\n"));
        write("# columns t_s robot x_mm y_mm heading_deg speed_l speed_r enc_l enc_r contact"
                + " prox0 prox1 prox2 prox3 prox4 prox5 prox6 prox7"
                + " light0 light1 light2 light3 light4 light5 light6 light7 arm fingers object held_cap\n");
        write("# caps t_s cap id x_mm y_mm held_by\n");
    }

    @Override
    public void onSnapshot(Snapshot snapshot) {
        for (RobotView r : snapshot.robots()) {
            line.setLength(0);
            Fixed.append(line, snapshot.timeNanos() / 1e9, 3).append(' ').append(r.id()).append(' ');
            Fixed.append(line, r.x(), 3).append(' ');
            Fixed.append(line, r.y(), 3).append(' ');
            Fixed.append(line, r.headingDeg(), 3).append(' ');
            line.append(r.speedLeft()).append(' ').append(r.speedRight()).append(' ')
                    .append(r.encoderLeft()).append(' ').append(r.encoderRight()).append(' ')
                    .append(r.contact().name());
            // Eight sensor columns whatever the robot: one with fewer writes 0 in the rest, one with more its first
            // eight.
            int n = r.sensorCount();
            for (int i = 0; i < 8; i++) {
                line.append(' ').append(i < n ? r.proximity(i) : 0);
            }
            for (int i = 0; i < 8; i++) {
                line.append(' ').append(i < n ? r.light(i) : 0);
            }
            GripperView g = r.gripper();
            line.append(' ').append(g.armPosition()).append(' ').append(g.fingers().name()).append(' ')
                    .append(g.objectPresent() ? 1 : 0).append(' ').append(g.heldCap());
            line.append('\n');
            write(line.toString());
        }
        List<CapView> caps = snapshot.caps();
        if (caps.size() != capX.length) {
            capX = new double[caps.size()];
            capY = new double[caps.size()];
            capHeld = new int[caps.size()];
            first = true;
        }
        for (CapView c : caps) {
            int i = c.id();
            if (first || c.x() != capX[i] || c.y() != capY[i] || c.heldBy() != capHeld[i]) {
                capX[i] = c.x();
                capY[i] = c.y();
                capHeld[i] = c.heldBy();
                line.setLength(0);
                Fixed.append(line, snapshot.timeNanos() / 1e9, 3).append(" cap ").append(i).append(' ');
                Fixed.append(line, c.x(), 3).append(' ');
                Fixed.append(line, c.y(), 3).append(' ').append(c.heldBy()).append('\n');
                write(line.toString());
            }
        }
        first = false;
        for (org.kheperasim.sim.engine.view.VisionView v : snapshot.vision()) {
            if (v.robot() >= visionTaken.length) {
                int old = visionTaken.length;
                visionTaken = java.util.Arrays.copyOf(visionTaken, v.robot() + 1);
                java.util.Arrays.fill(visionTaken, old, visionTaken.length, -1);
            }
            if (visionTaken[v.robot()] == v.takenNanos()) {
                continue;
            }
            visionTaken[v.robot()] = v.takenNanos();
            line.setLength(0);
            line.append(VISION_PREFIX);
            Fixed.append(line, snapshot.timeNanos() / 1e9, 3).append(' ').append(v.robot()).append(' ');
            Fixed.append(line, v.takenNanos() / 1e9, 3);
            for (int i = 0; i < v.pixels().length; i++) {
                line.append(' ').append(v.pixel(i));
            }
            line.append('\n');
            write(line.toString());
        }
    }

    /** How a vision line starts. */
    public static final String VISION_PREFIX = "# vision ";

    private void write(String text) {
        try {
            out.write(text);
        } catch (IOException e) {
            throw new UncheckedIOException("could not write the trace: " + e.getMessage(), e);
        }
        digest.update(text.getBytes(StandardCharsets.UTF_8));
    }

    /** @return the SHA-256 of everything written, hex; available after {@link #close()} */
    public String sha256() {
        return sha256;
    }

    @Override
    public void close() {
        if (sha256 == null) {
            sha256 = HexFormat.of().formatHex(digest.digest());
        }
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException("could not finish the trace: " + e.getMessage(), e);
        }
    }
}
