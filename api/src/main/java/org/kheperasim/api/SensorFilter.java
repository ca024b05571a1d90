package org.kheperasim.api;

import java.util.Arrays;

/**
 * Takes the random spikes out of sensor readings, the filtering the paper's students wrote by hand:
 * it keeps the last few readings of each sensor, answers their median, and tells when the newest
 * reading jumps further from the ones before it than normal noise does (a spike). A median of three
 * ignores any single spike and follows a real change one reading later; a window of five ignores two
 * spikes in a row and follows two readings later.
 *
 * <pre>{@code
 * SensorFilter prox = new SensorFilter();          // 8 sensors, median of 3, spikes over 200
 * ...
 * prox.add(sensors());                              // once per reading of the sensors
 * if (prox.value(IrSensor.FRONT_LEFT) > 500) { ... }
 * }</pre>
 *
 * <p>Plain Java with no clock of its own: it behaves the same in the simulator and on the robot.
 * Not thread-safe: use one filter per thread.
 */
public final class SensorFilter {
    /** Readings kept per sensor by default. */
    public static final int DEFAULT_WINDOW = 3;
    /** Default jump, in sensor units, above which a reading counts as a spike. */
    public static final int DEFAULT_SPIKE = 200;

    private final int window;
    private final int spike;
    private final int[][] recent;
    private final int[] count;
    private final int[] next;
    private final boolean[] lastSpike;
    private final int[] sorted;
    private long spikes;

    /** Eight sensors, the median of the last {@value #DEFAULT_WINDOW}, spikes over {@value #DEFAULT_SPIKE}. */
    public SensorFilter() {
        this(IrSensor.COUNT, DEFAULT_WINDOW, DEFAULT_SPIKE);
    }

    /**
     * @param sensors how many sensors (8 for the Khepera's proximity or light sensors)
     * @param window readings kept per sensor, odd, 1 to 15 (1 filters nothing)
     * @param spikeThreshold a reading further than this from the median of the ones before it is a spike
     * @throws IllegalArgumentException for a window that is even or out of range, or no sensors
     */
    public SensorFilter(int sensors, int window, int spikeThreshold) {
        if (sensors < 1) {
            throw new IllegalArgumentException("a filter needs at least one sensor, not " + sensors);
        }
        if (window < 1 || window > 15 || window % 2 == 0) {
            throw new IllegalArgumentException(
                    "the window must be odd and 1 to 15 readings (3 or 5 is usual), not " + window);
        }
        if (spikeThreshold < 0) {
            throw new IllegalArgumentException("the spike threshold must be 0 or more, not " + spikeThreshold);
        }
        this.window = window;
        this.spike = spikeThreshold;
        recent = new int[sensors][window];
        count = new int[sensors];
        next = new int[sensors];
        lastSpike = new boolean[sensors];
        sorted = new int[window];
    }

    /**
     * @param sensor which sensor, 0..sensors-1
     * @param reading its newest reading
     * @return the filtered value: the median of the last readings
     */
    public int add(int sensor, int reading) {
        int n = count[sensor];
        lastSpike[sensor] = n > 0 && StrictMath.abs(reading - median(sensor)) > spike;
        if (lastSpike[sensor]) {
            spikes++;
        }
        recent[sensor][next[sensor]] = reading;
        next[sensor] = (next[sensor] + 1) % window;
        if (n < window) {
            count[sensor] = n + 1;
        }
        return median(sensor);
    }

    /**
     * @param readings one reading per sensor, in index order
     * @return the filtered values
     */
    public int[] add(int[] readings) {
        int[] out = new int[readings.length];
        for (int i = 0; i < readings.length; i++) {
            out[i] = add(i, readings[i]);
        }
        return out;
    }

    /**
     * Reads every sensor's proximity value once and adds it.
     *
     * @param sensors the robot's sensors ({@code sensors()} in a controller)
     * @return the filtered proximity values
     */
    public int[] addProximity(Sensor[] sensors) {
        int[] raw = new int[sensors.length];
        for (int i = 0; i < sensors.length; i++) {
            raw[i] = sensors[i].getDistValue();
        }
        return add(raw);
    }

    /**
     * Reads every sensor's light value once and adds it.
     *
     * @param sensors the robot's sensors ({@code sensors()} in a controller)
     * @return the filtered light values
     */
    public int[] addLight(Sensor[] sensors) {
        int[] raw = new int[sensors.length];
        for (int i = 0; i < sensors.length; i++) {
            raw[i] = sensors[i].getLightValue();
        }
        return add(raw);
    }

    /**
     * @param sensor which sensor
     * @return its filtered value (0 before its first reading)
     */
    public int value(int sensor) {
        return count[sensor] == 0 ? 0 : median(sensor);
    }

    /**
     * @param sensor which sensor
     * @return its filtered value
     */
    public int value(IrSensor sensor) {
        return value(sensor.index());
    }

    /**
     * @param sensor which sensor
     * @return true when its newest reading was a spike
     */
    public boolean lastWasSpike(int sensor) {
        return lastSpike[sensor];
    }

    /** @return spikes seen since the filter was made or reset */
    public long spikes() {
        return spikes;
    }

    /** Forget every reading (after the robot was moved, say). */
    public void reset() {
        Arrays.fill(count, 0);
        Arrays.fill(next, 0);
        Arrays.fill(lastSpike, false);
        spikes = 0;
    }

    private int median(int sensor) {
        int n = count[sensor];
        System.arraycopy(recent[sensor], 0, sorted, 0, n);
        Arrays.sort(sorted, 0, n);
        return sorted[n / 2];
    }
}
