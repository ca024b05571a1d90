package org.kheperasim.sim.compare;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A run as a series of samples: time, the proximity readings, the wheel counters. Reads and writes
 * robot-link's recording format ({@code # khepera-link recording v2}: a line a poll cycle,
 * {@code t_s prox0..prox7 light0..light7 posL posR speedL speedR}).
 *
 * @param samples in time order
 */
public record Track(List<Point> samples) {
    /**
     * One sample.
     *
     * @param seconds time from the run's start, s
     * @param proximity the proximity readings
     * @param left the left wheel's counter, pulses
     * @param right the right wheel's counter, pulses
     */
    public record Point(double seconds, int[] proximity, int left, int right) {
    }

    /** Copies the list. */
    public Track {
        samples = List.copyOf(samples);
    }

    /**
     * @param file a robot-link recording
     * @return its samples
     * @throws IllegalArgumentException (one line naming the file and line) if it is not one
     */
    public static Track read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !(lines.get(0).startsWith("# khepera-link recording v1")
                || lines.get(0).startsWith("# khepera-link recording v2"))) {
            throw new IllegalArgumentException("recording " + file + " line 1 is not '# khepera-link recording v2':"
                    + " give a file written by 'khepera-link run --record'");
        }
        List<Point> out = new ArrayList<>();
        for (int n = 0; n < lines.size(); n++) {
            String l = lines.get(n).trim();
            // v2 keeps every line sent (>) and received (<) too; the track is the samples.
            if (l.isEmpty() || l.startsWith("#") || l.startsWith(">") || l.startsWith("<")) {
                continue;
            }
            String[] f = l.split("\\s+");
            if (f.length != 21) {
                throw new IllegalArgumentException("recording " + file + " line " + (n + 1) + " has " + f.length
                        + " fields: a sample line holds 21 (t_s prox0..7 light0..7 posL posR speedL speedR)");
            }
            try {
                int[] prox = new int[8];
                for (int i = 0; i < 8; i++) {
                    prox[i] = Integer.parseInt(f[1 + i]);
                }
                out.add(new Point(Double.parseDouble(f[0]), prox, Integer.parseInt(f[17]), Integer.parseInt(f[18])));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("recording " + file + " line " + (n + 1) + ": not numbers ("
                        + e.getMessage() + "): a sample line holds a time and whole numbers");
            }
        }
        if (out.isEmpty()) {
            throw new IllegalArgumentException("recording " + file + " has no samples: record a run of some seconds");
        }
        return new Track(out);
    }

    /** @param file where to write it in robot-link's recording format (the light and speed columns as 0) */
    public void write(Path file, String header) throws IOException {
        org.kheperasim.sim.files.AtomicFiles.write(file, text(header));
    }

    /** @param header what the run is @return it in robot-link's recording format (light and speeds as 0) */
    public String text(String header) {
        StringBuilder sb = new StringBuilder("# khepera-link recording v1\n# " + header
                + "\n# t_s prox0..prox7 light0..light7 posL posR speedL speedR\n");
        for (Point p : samples) {
            sb.append(String.format(Locale.ROOT, "%.4f", p.seconds()));
            for (int v : p.proximity()) {
                sb.append(' ').append(v);
            }
            sb.append(" 0 0 0 0 0 0 0 0 ").append(p.left()).append(' ').append(p.right()).append(" 0 0\n");
        }
        return sb.toString();
    }

    /** @param seconds a time @return the last sample at or before it (the first if none) */
    public Point at(double seconds) {
        int lo = 0;
        int hi = samples.size() - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (samples.get(mid).seconds() <= seconds + 1e-9) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return samples.get(lo);
    }

    /** @return the last sample's time, s */
    public double seconds() {
        return samples.get(samples.size() - 1).seconds();
    }
}
