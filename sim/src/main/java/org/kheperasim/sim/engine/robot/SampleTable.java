package org.kheperasim.sim.engine.robot;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * A sampled sensor table in the evorobotpy {@code .sample} format (Miglino, Lund and Nolfi 1995):
 * a real robot's readings of every sensor with an object at a number of distances and headings.
 *
 * <p>Layout: a first line {@code nsensors nangles ndistances initdist distinterval}; then, for each
 * distance block t, a line {@code TURN t} and {@code nangles} lines of {@code nsensors} activations
 * 0..1; then {@code END}. Block t lies {@code initdist + t * distinterval} mm from the robot's body
 * surface; heading index k puts the object {@code k * 360 / nangles} degrees to the robot's
 * <em>right</em> of straight ahead. Activations are read as the robot's 10-bit counts
 * ({@code value * 1023}, rounded).
 */
public final class SampleTable {
    /** The full scale of a reading, counts. */
    public static final int FULL_SCALE = 1023;

    private final String source;
    private final int sensors;
    private final int angles;
    private final int blocks;
    private final double initMm;
    private final double stepMm;
    /** {@code counts[block][angle][sensor]}. */
    private final int[][][] counts;

    private SampleTable(String source, int sensors, int angles, int blocks, double initMm, double stepMm,
            int[][][] counts) {
        this.source = source;
        this.sensors = sensors;
        this.angles = angles;
        this.blocks = blocks;
        this.initMm = initMm;
        this.stepMm = stepMm;
        this.counts = counts;
    }

    /**
     * @param file a {@code .sample} file
     * @return its table
     * @throws IOException if it cannot be read
     * @throws IllegalArgumentException (one line naming the file, the line and the fix) if it is not such a file
     */
    public static SampleTable read(Path file) throws IOException {
        return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.toString());
    }

    /**
     * @param lines the file's lines
     * @param source its name, for messages
     * @return its table
     */
    public static SampleTable parse(List<String> lines, String source) {
        if (lines.isEmpty()) {
            throw bad(source, 1, "is empty",
                    "the first line must be 'nsensors nangles ndistances initdist distinterval'");
        }
        String[] head = lines.get(0).trim().split("\\s+");
        if (head.length != 5) {
            throw bad(source, 1, "has '" + lines.get(0).trim() + "'", "the first line must be five numbers:"
                    + " nsensors nangles ndistances initdist distinterval");
        }
        int ns = positive(head[0], source, "nsensors");
        int na = positive(head[1], source, "nangles");
        int nd = positive(head[2], source, "ndistances");
        double init = number(head[3], source, 1);
        double step = number(head[4], source, 1);
        if (!(step > 0) || init < 0) {
            throw bad(source, 1, "has initdist " + head[3] + " and distinterval " + head[4],
                    "give initdist >= 0 and distinterval > 0, in mm");
        }
        int[][][] c = new int[nd][na][ns];
        int line = 1;
        for (int t = 0; t < nd; t++) {
            String turn = line < lines.size() ? lines.get(line).trim() : "";
            if (!turn.equals("TURN " + t)) {
                throw bad(source, line + 1, "has '" + turn + "'",
                        "expected 'TURN " + t + "' (" + nd + " blocks of " + na + " lines)");
            }
            line++;
            for (int k = 0; k < na; k++) {
                String row = line < lines.size() ? lines.get(line).trim() : "";
                String[] v = row.isEmpty() ? new String[0] : row.split("\\s+");
                if (v.length != ns) {
                    throw bad(source, line + 1, "has " + v.length + " values",
                            "give " + ns + " activations 0..1 per line");
                }
                for (int s = 0; s < ns; s++) {
                    double a = number(v[s], source, line + 1);
                    if (!(a >= 0 && a <= 1)) {
                        throw bad(source, line + 1, "has activation " + v[s], "activations lie in 0..1");
                    }
                    c[t][k][s] = (int) StrictMath.rint(a * FULL_SCALE);
                }
                line++;
            }
        }
        String end = line < lines.size() ? lines.get(line).trim() : "";
        if (!end.equals("END")) {
            throw bad(source, line + 1, "has '" + end + "'", "the table ends with a line 'END'");
        }
        return new SampleTable(source, ns, na, nd, init, step, c);
    }

    /** @return where the table came from (its file) */
    public String source() {
        return source;
    }

    /** @return how many sensors each line holds */
    public int sensors() {
        return sensors;
    }

    /** @return how many headings each block holds */
    public int angles() {
        return angles;
    }

    /** @return how many distance blocks it holds */
    public int blocks() {
        return blocks;
    }

    /** @param block a distance block @return its distance from the robot's body surface, mm */
    public double gapMm(int block) {
        return initMm + block * stepMm;
    }

    /** @param angle a heading index @return where the object lies, degrees to the robot's right of ahead, 0..360 */
    public double objectRightDeg(int angle) {
        return angle * 360.0 / angles;
    }

    /**
     * @param block a distance block
     * @param angle a heading index
     * @param sensor a sensor, in the file's (K-Team) order
     * @return the reading, counts 0..1023
     */
    public int counts(int block, int angle, int sensor) {
        return counts[block][angle][sensor];
    }

    /**
     * The light table's activations rise with the light, the robot's ambient readings fall with it;
     * the transform is not published. This takes the K-Team manual's figures: about {@code dark} in
     * darkness (activation 0) down to {@code bright} next to the lamp (activation 1), linearly.
     *
     * @param counts an activation as counts (0..1023)
     * @param dark the ambient reading in darkness, counts (the manual: about 450..500)
     * @param bright the ambient reading at the lamp, counts (the manual: 20 or less)
     * @return the ambient reading, counts
     */
    public static double ambientReading(int counts, double dark, double bright) {
        return dark - (dark - bright) * counts / FULL_SCALE;
    }

    private static int positive(String v, String source, String what) {
        try {
            int n = Integer.parseInt(v);
            if (n > 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw bad(source, 1, "has " + what + " '" + v + "'", "give a whole number above 0");
    }

    private static double number(String v, String source, int line) {
        if (!v.matches("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+")) {
            throw bad(source, line, "has '" + v + "'", "write plain decimal numbers, like 0.25");
        }
        return Double.parseDouble(v);
    }

    private static IllegalArgumentException bad(String source, int line, String what, String fix) {
        return new IllegalArgumentException(
                String.format(Locale.ROOT, "sample table %s line %d %s: %s", source, line, what, fix));
    }
}
