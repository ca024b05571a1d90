package org.kheperasim.sim.engine.robot;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Proximity responses fitted to sampled wall tables, as {@code prox.profile=sample:PATH} names them
 * (a {@code .sample} file of the evorobotpy format, {@link SampleTable}): the file is read and fitted
 * ({@link SampleFit}) once per path and run. The fit's per-sensor gains are not part of a response;
 * {@link SampleFit.Result#gains()} gives them, for {@code prox.N.gain}.
 */
public final class SampleResponses {
    /** The prefix of a {@code prox.profile} value that names a sample file. */
    public static final String PREFIX = "sample:";

    private static final Map<String, SampleFit.Result> FITS = new ConcurrentHashMap<>();

    private SampleResponses() {
    }

    /**
     * @param path a {@code .sample} file of wall readings
     * @param type the robot that took them (its radius and sensor poses)
     * @return the fit
     * @throws IllegalArgumentException (one line) if the file is missing or not a sample table
     */
    public static SampleFit.Result fit(String path, RobotType type) {
        return FITS.computeIfAbsent(path + "\n" + type.name(), k -> {
            Path file = Path.of(path);
            if (!Files.isRegularFile(file)) {
                throw new IllegalArgumentException("sample table " + path + " does not exist: give the path of a"
                        + " .sample file, e.g. prox.profile=sample:../shared/real-khepera/khepera-wall.sample");
            }
            try {
                return SampleFit.fit(type, samples(SampleTable.read(file), type));
            } catch (IOException e) {
                throw new IllegalArgumentException("sample table " + path + " cannot be read (" + e.getMessage()
                        + "): check the file's permissions");
            }
        });
    }

    /**
     * @param table a sampled wall table
     * @param type the robot that took it
     * @return its readings, the sensors the robot has
     */
    public static List<SampleFit.Sample> samples(SampleTable table, RobotType type) {
        if (table.sensors() != type.sensorCount()) {
            throw new IllegalArgumentException("sample table " + table.source() + " has " + table.sensors()
                    + " sensors but robot " + type.name() + " has " + type.sensorCount()
                    + ": use a table of that robot");
        }
        List<SampleFit.Sample> out = new ArrayList<>();
        for (int t = 0; t < table.blocks(); t++) {
            for (int k = 0; k < table.angles(); k++) {
                for (int i = 0; i < table.sensors(); i++) {
                    out.add(new SampleFit.Sample(i, table.gapMm(t), table.objectRightDeg(k), table.counts(t, k, i)));
                }
            }
        }
        return out;
    }
}
