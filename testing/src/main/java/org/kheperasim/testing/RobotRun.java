package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What one robot did in a {@link Run}: where it went, what it touched and when, which regions it entered
 * and when, and how its controller ended. Immutable.
 */
public final class RobotRun {
    private final int index;
    private final String name;
    private final String controller;
    private final List<PathPoint> path;
    private final List<Contact> contacts;
    private final Map<String, SimTime> regionsEntered;
    private final Ending ending;
    private final double distanceMm;
    private final int collisions;
    private final double visitedPercent;
    /** The run this robot is part of: set once, by the run's constructor. */
    private Run run;

    RobotRun(int index, String name, String controller, List<PathPoint> path, List<Contact> contacts,
            Map<String, SimTime> regionsEntered, Ending ending, double distanceMm, int collisions,
            double visitedPercent) {
        this.index = index;
        this.name = name;
        this.controller = controller;
        this.path = List.copyOf(path);
        this.contacts = List.copyOf(contacts);
        this.regionsEntered = Collections.unmodifiableMap(new LinkedHashMap<>(regionsEntered));
        this.ending = ending;
        this.distanceMm = distanceMm;
        this.collisions = collisions;
        this.visitedPercent = visitedPercent;
    }

    /** @param owner the run this robot is part of */
    void partOf(Run owner) {
        if (run != null) {
            throw new IllegalStateException("robot " + index + " is already part of a run");
        }
        run = owner;
    }

    /** @return the run this robot is part of */
    Run run() {
        return run;
    }

    /** @return the robot's index: 0 for the arena's first {@code robot} line */
    public int index() {
        return index;
    }

    /**
     * @return the robot's name in messages: its controller's simple class name, with {@code #index} when the run has
     *     several robots
     */
    public String name() {
        return name;
    }

    /** @return its controller's class name */
    public String controller() {
        return controller;
    }

    /** @return where it started (the first sample) */
    public Pose start() {
        return path.get(0).pose();
    }

    /** @return where it was at the end of the run (the last sample, written at the run's end) */
    public Pose finalPose() {
        return path.get(path.size() - 1).pose();
    }

    /**
     * @return its path: one point per sample of the run's trace, from the start to the end, in time order
     *     (every 50 ms of simulated time unless {@link RunBuilder#sampleEvery} says otherwise)
     */
    public List<PathPoint> path() {
        return path;
    }

    /**
     * @param t a simulated time within the run
     * @return where the robot was at the last sample at or before {@code t}
     */
    public Pose poseAt(SimTime t) {
        PathPoint at = path.get(0);
        for (PathPoint p : path) {
            if (p.time().isAfter(t)) {
                break;
            }
            at = p;
        }
        return at.pose();
    }

    /** @return every time its body touched something, in time order (see {@link Contact} for how they are seen) */
    public List<Contact> contacts() {
        return contacts;
    }

    /**
     * @param what a kind of obstacle
     * @return its contacts with that kind, in time order
     */
    public List<Contact> contactsWith(Obstacle what) {
        List<Contact> out = new ArrayList<>();
        for (Contact c : contacts) {
            if (c.what() == what) {
                out.add(c);
            }
        }
        return out;
    }

    /**
     * @return the named regions of the arena its centre entered, each with the first time it did, in the
     *     arena's order of regions. In a run made by {@link RunBuilder#run()} the simulator checks every
     *     millisecond; in a run read from a trace, every sample.
     */
    public Map<String, SimTime> regionsEntered() {
        return regionsEntered;
    }

    /**
     * @param region a region's name, as in the arena file
     * @return when the robot's centre first entered it, or empty when it never did
     */
    public Optional<SimTime> entered(String region) {
        return Optional.ofNullable(regionsEntered.get(region));
    }

    /** @return how its controller ended */
    public Ending ending() {
        return ending;
    }

    /** @return the length of its path, mm (the simulator's own measure; from the samples for a trace) */
    public double distanceMm() {
        return distanceMm;
    }

    /**
     * @return how many times an obstacle stopped one of its moves, as the simulator counts them; -1 for a
     *     run read from a trace (a trace does not record it)
     */
    public int collisions() {
        return collisions;
    }

    /**
     * @return the share of the floor its body covered, percent (what a {@code task cover} scores); NaN for a
     *     run read from a trace (a trace does not record it)
     */
    public double visitedPercent() {
        return visitedPercent;
    }

    /** @return e.g. {@code MyController (robot 0) ended at (380.0, 610.2) mm heading 90.0 deg} */
    @Override
    public String toString() {
        return name + " (robot " + index + ") ended at " + finalPose();
    }
}
