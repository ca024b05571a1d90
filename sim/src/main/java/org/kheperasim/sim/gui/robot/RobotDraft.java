package org.kheperasim.sim.gui.robot;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.kheperasim.sim.engine.robot.ProximityProfile;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot being edited: one {@link RobotType} at a time, replaced whole by each edit once the
 * edit passes {@link RobotChecks} and the robot file's own reader ({@link RobotFileStore#problem});
 * the file it came from or was saved to, whether it has changed since, and the sensor chosen.
 * A refused edit changes nothing and returns its one-line reason.
 */
final class RobotDraft {
    private final RobotFileStore store;
    private final List<Runnable> listeners = new ArrayList<>();
    private RobotType type;
    private Path file;
    private boolean dirty;
    private int selected;

    /**
     * @param store the robot files' reader, for its checks @param type the robot to start from @param file its file, or
     *     null
     */
    RobotDraft(RobotFileStore store, RobotType type, Path file) {
        this.store = store;
        this.type = type;
        this.file = file;
    }

    /** @return the robot as edited */
    RobotType type() {
        return type;
    }

    /** @return the file it was read from or saved to, or null */
    Path file() {
        return file;
    }

    /** @return whether it changed since it was opened or saved */
    boolean dirty() {
        return dirty;
    }

    /** @return the chosen sensor's index */
    int selected() {
        return selected;
    }

    /** @param i a sensor to choose (clamped to the robot's sensors) */
    void select(int i) {
        int next = StrictMath.max(0, StrictMath.min(type.sensorCount() - 1, i));
        if (next != selected) {
            selected = next;
            fire();
        }
    }

    /** @param l called after every change (on the caller's thread) */
    void onChange(Runnable l) {
        listeners.add(l);
    }

    /** @param t another robot, loaded whole @param f its file, or null */
    void load(RobotType t, Path f) {
        type = t;
        file = f;
        dirty = false;
        selected = 0;
        fire();
    }

    /** @param f the file just written */
    void saved(Path f) {
        file = f;
        dirty = false;
        fire();
    }

    /** @param next the robot after an edit @return null when applied, else why it was refused (nothing changed) */
    String apply(RobotType next) {
        if (next.equals(type)) {
            return null;
        }
        String p = RobotChecks.problem(next);
        if (p == null) {
            p = store.problem(next);
        }
        if (p != null) {
            return p;
        }
        type = next;
        dirty = true;
        selected = StrictMath.min(selected, type.sensorCount() - 1);
        fire();
        return null;
    }

    String setName(String name) {
        return apply(new RobotType(name, type.source(), type.body(), type.drive(), type.sensors(),
                named(type.proximity(), name),
                type.light(), type.turrets(), type.dialect(), type.measured()));
    }

    /**
     * A robot file's curve goes by its robot's name: a renamed robot's curve is renamed with it, so
     * that the robot edited is the robot its saved file reads back as.
     *
     * @param p a proximity response @param robot the robot's name @return p, its curve named after the robot
     */
    static RobotType.Proximity named(RobotType.Proximity p, String robot) {
        if (!(p.response() instanceof Response.Curve c) || c.distance().name().equals(robot)) {
            return p;
        }
        Response.Curve renamed = new Response.Curve(new ProximityProfile(robot, c.distance().distancesMm(),
                c.distance().values()), c.anglesDeg(), c.weights());
        return new RobotType.Proximity(renamed, p.offset(), p.noiseAbs(), p.noiseRel(), p.maxReading());
    }

    String setBodyRadius(double mm) {
        return apply(new RobotType(type.name(), type.source(), new RobotType.Body(mm), type.drive(), type.sensors(),
                type.proximity(), type.light(), type.turrets(), type.dialect(), type.measured()));
    }

    String setWheelBase(double mm) {
        RobotType.Drive d = type.drive();
        return drive(new RobotType.Drive(mm, d.mmPerSecondPerUnit(), d.maxSpeed(), d.mmPerPulse(), d.motorPeriodNanos(),
                d.noisePeriodNanos(), d.moveSpeed(), d.acceleration()));
    }

    String setSpeedUnit(double mmPerSecond) {
        RobotType.Drive d = type.drive();
        return drive(new RobotType.Drive(d.wheelBaseMm(), mmPerSecond, d.maxSpeed(), d.mmPerPulse(),
                d.motorPeriodNanos(),
                d.noisePeriodNanos(), d.moveSpeed(), d.acceleration()));
    }

    String setMaxSpeed(int units) {
        RobotType.Drive d = type.drive();
        return drive(new RobotType.Drive(d.wheelBaseMm(), d.mmPerSecondPerUnit(), units, d.mmPerPulse(),
                d.motorPeriodNanos(),
                d.noisePeriodNanos(), d.moveSpeed(), d.acceleration()));
    }

    private String drive(RobotType.Drive d) {
        return apply(new RobotType(type.name(), type.source(), type.body(), d, type.sensors(), type.proximity(),
                type.light(), type.turrets(), type.dialect(), type.measured()));
    }

    /** @param i a sensor @param x mm forward @param y mm left @return null, or why not */
    String moveSensor(int i, double x, double y) {
        return sensor(i, s -> new RobotType.Sensor(s.name(), s.channel(), x, y, s.headingDeg()));
    }

    /** @param i a sensor @param deg its heading, normalised to (-180, 180] @return null, or why not */
    String turnSensor(int i, double deg) {
        double h = normalised(deg);
        return sensor(i, s -> new RobotType.Sensor(s.name(), s.channel(), s.xMm(), s.yMm(), h));
    }

    String renameSensor(int i, String name) {
        return sensor(i, s -> new RobotType.Sensor(name, s.channel(), s.xMm(), s.yMm(), s.headingDeg()));
    }

    private String sensor(int i, Function<RobotType.Sensor, RobotType.Sensor> edit) {
        List<RobotType.Sensor> list = new ArrayList<>(type.sensors());
        list.set(i, edit.apply(list.get(i)));
        return sensors(list);
    }

    /** A sensor more, at the front edge of the body looking ahead, on the next free channel; it is chosen. */
    String addSensor() {
        List<RobotType.Sensor> list = new ArrayList<>(type.sensors());
        int channel = 0;
        for (RobotType.Sensor s : list) {
            channel = StrictMath.max(channel, s.channel() + 1);
        }
        int k = list.size();
        String name = "S" + k;
        while (nameTaken(list, name)) {
            k++;
            name = "S" + k;
        }
        list.add(new RobotType.Sensor(name, channel, type.body().radiusMm() * 0.9, 0, 0));
        String p = sensors(list);
        if (p == null) {
            select(list.size() - 1);
        }
        return p;
    }

    /**
     * @param i the sensor to take away (a robot keeps one at least); the channels above its close up
     * @return null, or why not
     */
    String removeSensor(int i) {
        if (type.sensorCount() == 1) {
            return "the robot's only sensor cannot go; a robot has one sensor at least";
        }
        List<RobotType.Sensor> list = new ArrayList<>();
        int gone = type.sensor(i).channel();
        for (int k = 0; k < type.sensorCount(); k++) {
            RobotType.Sensor s = type.sensor(k);
            if (k != i) { // the channels stay 0 to n-1, each once, as a robot file numbers them
                int c = s.channel() > gone ? s.channel() - 1 : s.channel();
                list.add(new RobotType.Sensor(s.name(), c, s.xMm(), s.yMm(), s.headingDeg()));
            }
        }
        return sensors(list);
    }

    private String sensors(List<RobotType.Sensor> list) {
        return apply(new RobotType(type.name(), type.source(), type.body(), type.drive(), list, type.proximity(),
                type.light(), type.turrets(), type.dialect(), keptMeasurement(list)));
    }

    private static boolean nameTaken(List<RobotType.Sensor> list, String name) {
        return list.stream().anyMatch(s -> s.name().equals(name));
    }

    /** @param deg an angle @return the same direction in (-180, 180] */
    static double normalised(double deg) {
        double h = deg % 360;
        if (h > 180) {
            h -= 360;
        } else if (h <= -180) {
            h += 360;
        }
        return h == 0 ? 0 : h; // no -0
    }

    private void fire() {
        for (Runnable l : listeners) {
            l.run();
        }
    }

    /** @return the calibration's numbers while each sensor still has its gain; none once sensors come or go */
    private RobotType.Measured keptMeasurement(java.util.List<RobotType.Sensor> sensors) {
        RobotType.Measured m = type.measured();
        return m != null && m.proxGains().size() == sensors.size() ? m : null;
    }
}
