package org.kheperasim.sim.engine.robot;

/**
 * What one beam of a proximity sensor gives for a hit: the sensor, the beam (the axis, then a pair at
 * plus and minus each further angle of the robot's {@link Response}), the distance along it and the
 * kind of object it met. The engine casts the beams and finds the hits; this is asked for the reading.
 *
 * <p>A kind of robot has one response for every sensor, times a reflectance per kind of object
 * ({@code prox.reflect.*}). A measured robot ({@link MeasuredTables}) may have a wall table per sensor
 * and tables per kind of object (a cap, another robot), each read at the beam's angle (interpolated
 * between the table's angles) and distance; a kind without its own table reads the sensor's wall
 * table times its reflectance. Beams reach as far as the robot's response does
 * ({@link #rangeMm()}), whatever a table's own range.
 */
public final class BeamResponse {
    /** Kinds of object, as the reflectance table indexes them: the floor, a wall, a lamp's body, a cap. */
    public static final int FLOOR = 0;
    /** A wall. */
    public static final int WALL = 1;
    /** A lamp's body. */
    public static final int LIGHT = 2;
    /** A cap. */
    public static final int CAP = 3;
    /** Another robot's body. */
    public static final int ROBOT = 4;

    private final double[] reflectance;
    private final double maxReflectance;
    private final double range;
    /** The shared response along each beam, and its weight (a kind of robot). */
    private final ProximityProfile[] profile;
    private final double[] weight;
    /** A measured robot's tables per beam, or null: {@code [sensor][ray]} for the wall, {@code [ray]} per kind. */
    private final Beam[][] wall;
    private final Beam[][] cap;
    private final Beam[][] robot;

    /**
     * @param response the robot's response (its beams' angles and range)
     * @param reflectance by kind of object ({@link #FLOOR} .. {@link #ROBOT}), the wall being the reference
     * @param tables what was measured on this robot, or null (a kind of robot)
     * @param sensors how many sensors the robot has
     */
    public BeamResponse(Response response, double[] reflectance, MeasuredTables tables, int sensors) {
        this.reflectance = reflectance.clone();
        this.maxReflectance = StrictMath.max(StrictMath.max(reflectance[WALL], reflectance[ROBOT]),
                StrictMath.max(reflectance[LIGHT], reflectance[CAP]));
        this.range = response.rangeMm();
        double[] angles = response.anglesDeg();
        int rays = 2 * angles.length - 1;
        profile = new ProximityProfile[rays];
        weight = new double[rays];
        double[] rayDeg = new double[rays];
        for (int r = 0; r < rays; r++) {
            int j = (r + 1) / 2;
            rayDeg[r] = angles[j];
            profile[r] = response.along(j);
            weight[r] = response.weight(j);
        }
        if (tables == null || !tables.hasProximityTables()) {
            wall = null;
            cap = null;
            robot = null;
            return;
        }
        wall = new Beam[sensors][];
        for (int i = 0; i < sensors; i++) {
            wall[i] = beams(tables.sensors().isEmpty() ? response : tables.sensors().get(i), rayDeg);
        }
        cap = kind(tables.cap(), sensors, rayDeg);
        robot = kind(tables.robot(), sensors, rayDeg);
    }

    /**
     * The beams' response of a robot: its measured tables when it has some, else the kind's response.
     *
     * @param type the robot (its sensors, and what was measured on it)
     * @param response the proximity response the run uses (the robot's, or the settings' in its place)
     * @param reflectance by kind of object, the wall being the reference
     * @return its beams' response
     */
    public static BeamResponse of(RobotType type, Response response, double[] reflectance) {
        return new BeamResponse(response, reflectance, type.measured() == null ? null : type.measured().tables(),
                type.sensorCount());
    }

    /** @return how far the beams reach, mm: the robot's response's range */
    public double rangeMm() {
        return range;
    }

    /** @return the largest reflectance of a wall, a lamp, a cap or a robot */
    public double maxReflectance() {
        return maxReflectance;
    }

    /**
     * @param sensor a sensor
     * @param ray a beam: 0 the axis, then {@code 2j - 1} and {@code 2j} the pair at the response's angle j
     * @param kind what the beam met ({@link #WALL}, {@link #LIGHT}, {@link #CAP}, {@link #ROBOT})
     * @param mm the distance along the beam, mm
     * @return the beam's response, before the sensor's gain, offset and noise
     */
    public double value(int sensor, int ray, int kind, double mm) {
        if (wall == null) {
            return weight[ray] * reflectance[kind] * profile[ray].valueAt(mm);
        }
        if (kind == CAP && cap != null) {
            return cap[sensor][ray].at(mm);
        }
        if (kind == ROBOT && robot != null) {
            return robot[sensor][ray].at(mm);
        }
        return reflectance[kind] * wall[sensor][ray].at(mm);
    }

    /**
     * @param sensor a sensor
     * @param ray a beam
     * @param v a response
     * @return a distance beyond which no object along that beam gives more than {@code v}
     */
    public double beyondAtMost(int sensor, int ray, double v) {
        if (wall == null) {
            return profile[ray].distanceBeyondWhichAtMost(v / (weight[ray] * maxReflectance));
        }
        double d = wall[sensor][ray].beyondAtMost(v / maxReflectance);
        if (cap != null) {
            d = StrictMath.max(d, cap[sensor][ray].beyondAtMost(v));
        }
        if (robot != null) {
            d = StrictMath.max(d, robot[sensor][ray].beyondAtMost(v));
        }
        return d;
    }

    /** @param sensor a sensor @return its response touching a wall on its axis (the lowered gripper arm) */
    public double touching(int sensor) {
        return wall == null ? reflectance[WALL] * profile[0].valueAt(0) : reflectance[WALL] * wall[sensor][0].at(0);
    }

    /** @return a kind's tables by sensor and beam (one table for all, or one a sensor); null: none */
    private static Beam[][] kind(java.util.List<Response> tables, int sensors, double[] rayDeg) {
        if (tables.isEmpty()) {
            return null;
        }
        Beam[][] out = new Beam[sensors][];
        for (int i = 0; i < sensors; i++) {
            out[i] = i > 0 && tables.size() == 1 ? out[0] : beams(tables.get(tables.size() == 1 ? 0 : i), rayDeg);
        }
        return out;
    }

    private static Beam[] beams(Response t, double[] rayDeg) {
        double[] a = t.anglesDeg();
        Beam[] out = new Beam[rayDeg.length];
        for (int r = 0; r < rayDeg.length; r++) {
            double x = rayDeg[r];
            if (x > a[a.length - 1]) {
                out[r] = new Beam(null, null, 0, 0);
                continue;
            }
            int j = 0;
            while (j + 1 < a.length && a[j + 1] < x) {
                j++;
            }
            double f = j + 1 >= a.length || x <= a[j] ? 0 : (x - a[j]) / (a[j + 1] - a[j]);
            out[r] = new Beam(t.along(j), f > 0 ? t.along(j + 1) : null, t.weight(j) * (1 - f),
                    f > 0 ? t.weight(j + 1) * f : 0);
        }
        return out;
    }

    /** A table read at one beam's angle: between two of its rows, each weighted. */
    private record Beam(ProximityProfile low, ProximityProfile high, double lowWeight, double highWeight) {
        double at(double mm) {
            if (low == null) {
                return 0;
            }
            double v = lowWeight * low.valueAt(mm);
            return high == null ? v : v + highWeight * high.valueAt(mm);
        }

        double beyondAtMost(double v) {
            if (low == null) {
                return 0;
            }
            double d = low.distanceBeyondWhichAtMost(v / (lowWeight + highWeight));
            return high == null ? d : StrictMath.max(d, high.distanceBeyondWhichAtMost(v / (lowWeight + highWeight)));
        }
    }
}
