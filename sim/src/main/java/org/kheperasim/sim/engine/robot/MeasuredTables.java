package org.kheperasim.sim.engine.robot;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * What a calibration or a measured robot file gives beyond one response for the kind: a table per
 * sensor (its own shape over distance and angle, for the white wall), tables per kind of object (a
 * cap, another robot: one for every sensor, or one a sensor), each sensor's measured noise, and the
 * light sensors' response to a lamp. Every part is optional: an empty list or null keeps the kind's
 * (the type's response, the settings' reflectances, the modelled lamp fall-off). {@link BeamResponse}
 * asks them for a beam's reading.
 *
 * @param sensors one wall table per sensor, in sensor order (empty: the type's response for all, with
 *     {@link RobotType.Measured#proxGains()} as each one's gain)
 * @param cap the response to a cap, in place of the wall's times {@code prox.reflect.cap}: one table for
 *     every sensor, or one a sensor (empty: the wall's times the reflectance)
 * @param robot the response to another robot's body, in place of the wall's times {@code prox.reflect.robot}
 * @param noiseScale each sensor's measured noise over the type's (empty: 1 each)
 * @param lamp the light sensors' response to a lamp (null: the modelled fall-off)
 */
public record MeasuredTables(List<Response> sensors, List<Response> cap, List<Response> robot,
        List<Double> noiseScale, LampResponse lamp) {
    /** Nothing measured beyond the kind. */
    public static final MeasuredTables NONE = new MeasuredTables(List.of(), List.of(), List.of(), List.of(), null);

    public MeasuredTables {
        sensors = List.copyOf(sensors);
        cap = List.copyOf(cap);
        robot = List.copyOf(robot);
        noiseScale = List.copyOf(noiseScale);
    }

    /** @return whether it holds nothing (the robot reads as its kind, with its gains) */
    public boolean isEmpty() {
        return sensors.isEmpty() && cap.isEmpty() && robot.isEmpty() && noiseScale.isEmpty() && lamp == null;
    }

    /** @return whether it holds a proximity table (per sensor or per kind of object) */
    public boolean hasProximityTables() {
        return !sensors.isEmpty() || !cap.isEmpty() || !robot.isEmpty();
    }

    /** @return the first of its proximity tables (all share one grid), or null when it has none */
    public Response.Table grid() {
        List<Response> all = all();
        return all.isEmpty() ? null : (Response.Table) all.get(0);
    }

    /** @param i a sensor @return its noise over the type's */
    public double noiseScale(int i) {
        return noiseScale.isEmpty() ? 1 : noiseScale.get(i);
    }

    /** @param s per-sensor wall tables @return these tables with them */
    public MeasuredTables withSensors(List<Response> s) {
        return new MeasuredTables(s, cap, robot, noiseScale, lamp);
    }

    /** @param c a cap's tables @param r another robot's @return these tables with them */
    public MeasuredTables withObjects(List<Response> c, List<Response> r) {
        return new MeasuredTables(sensors, c, r, noiseScale, lamp);
    }

    /** @param c a cap's table for every sensor, or null @param r another robot's @return these tables with them */
    public MeasuredTables withObjects(Response c, Response r) {
        return withObjects(c == null ? List.of() : List.of(c), r == null ? List.of() : List.of(r));
    }

    /** @param n each sensor's noise scale @return these tables with it */
    public MeasuredTables withNoise(List<Double> n) {
        return new MeasuredTables(sensors, cap, robot, n, lamp);
    }

    /** @param l the lamp response @return these tables with it */
    public MeasuredTables withLamp(LampResponse l) {
        return new MeasuredTables(sensors, cap, robot, noiseScale, l);
    }

    private List<Response> all() {
        List<Response> all = new ArrayList<>(sensors);
        all.addAll(cap);
        all.addAll(robot);
        return all;
    }

    /** Checks the tables against a robot's sensor count. */
    void check(String robotName, int sensorCount) {
        Objects.requireNonNull(robotName);
        if (!sensors.isEmpty() && sensors.size() != sensorCount) {
            throw new IllegalArgumentException("robot " + robotName + " has " + sensorCount + " sensors but "
                    + sensors.size() + " measured wall tables: give one table a sensor");
        }
        for (List<Response> kind : List.of(cap, robot)) {
            if (kind.size() > 1 && kind.size() != sensorCount) {
                throw new IllegalArgumentException("robot " + robotName + " has " + sensorCount + " sensors but "
                        + kind.size() + " tables for one kind of object: give one for every sensor, or one a sensor");
            }
        }
        Response.Table grid = null;
        for (Response r : all()) {
            if (!(r instanceof Response.Table t)) {
                throw new IllegalArgumentException("robot " + robotName + ": a measured table must be a table (a"
                        + " value for each angle and distance), not a curve");
            }
            if (grid == null) {
                grid = t;
            } else if (!Arrays.equals(grid.anglesDeg(), t.anglesDeg())
                    || !Arrays.equals(grid.distancesMm(), t.distancesMm())) {
                throw new IllegalArgumentException("robot " + robotName + ": its measured tables must share their"
                        + " angles and distances (a robot file writes them once, table_angles and table_distances)");
            }
        }
        if (!noiseScale.isEmpty() && noiseScale.size() != sensorCount) {
            throw new IllegalArgumentException("robot " + robotName + " has " + sensorCount + " sensors but "
                    + noiseScale.size() + " noise scales: give one a sensor");
        }
    }
}
