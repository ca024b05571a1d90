package org.kheperasim.sim.arena;

import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * A complete arena: its size, where the robots start, and the fixed and movable objects on the
 * floor. Millimetres throughout; x to the right, y up, origin at the lower-left corner.
 *
 * <p>Immutable; the lists are unmodifiable copies. The record checks only what keeps the model
 * consistent (positive size, at least one robot, unique region names); {@link ArenaFormat#parse}
 * additionally checks that everything lies inside the arena and that no robot starts inside a
 * wall or lamp.
 *
 * @param name    identifier of letters, digits, {@code _} and {@code -}
 * @param width   extent along x, mm, greater than 0
 * @param height  extent along y, mm, greater than 0
 * @param robots  start poses, one per robot, at least one
 * @param walls   fixed walls
 * @param lights  fixed lamps
 * @param caps    movable bottle caps, in the order that gives them their grid ids
 * @param regions named rectangles, names unique
 * @param assignment what a run is scored on (tasks, time limit); {@link Assignment#NONE} for none
 * @param robotKinds each robot's type, in the order of {@code robots} (the arena's {@code robot}
 *     line names it; {@link RobotKind#DEFAULT}, the Khepera I, when it does not)
 */
public record Arena(String name, double width, double height, List<Pose> robots, List<Wall> walls,
                    List<Light> lights, List<Cap> caps, List<Region> regions, Assignment assignment,
                    List<RobotKind> robotKinds) {

    /**
     * @throws IllegalArgumentException if the name is not an identifier, the size is not positive or
     *                                  beyond {@link ArenaLimits},
     *                                  there is no robot, or two regions share a name
     * @throws NullPointerException     if a list or an element is null
     */
    public Arena {
        if (name == null || !Region.NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("arena name '" + name
                    + "' is not allowed; use letters, digits, '_' and '-' only");
        }
        width = Numbers.positive("arena width", width, "mm");
        height = Numbers.positive("arena height", height, "mm");
        ArenaLimits.checkSize(width, height);
        robots = List.copyOf(robots);
        walls = List.copyOf(walls);
        lights = List.copyOf(lights);
        caps = List.copyOf(caps);
        regions = List.copyOf(regions);
        java.util.Objects.requireNonNull(assignment, "assignment");
        robotKinds = List.copyOf(robotKinds);
        if (robotKinds.size() != robots.size()) {
            throw new IllegalArgumentException("arena '" + name + "' has " + robots.size() + " robots but "
                    + robotKinds.size() + " robot types; give each robot its type");
        }
        if (robots.isEmpty()) {
            throw new IllegalArgumentException("arena '" + name + "' has no robot; add a start pose");
        }
        Set<String> names = new HashSet<>();
        for (Region r : regions) {
            if (!names.add(r.name())) {
                throw new IllegalArgumentException("region name '" + r.name()
                        + "' is used twice; give each region its own name");
            }
        }
    }

    /**
     * An arena whose robots are all Khepera Is ({@link RobotKind#DEFAULT}).
     *
     * @param name    identifier of letters, digits, {@code _} and {@code -}
     * @param width   extent along x, mm
     * @param height  extent along y, mm
     * @param robots  start poses
     * @param walls   fixed walls
     * @param lights  fixed lamps
     * @param caps    movable bottle caps
     * @param regions named rectangles
     * @param assignment what a run is scored on
     */
    public Arena(String name, double width, double height, List<Pose> robots, List<Wall> walls,
                 List<Light> lights, List<Cap> caps, List<Region> regions, Assignment assignment) {
        this(name, width, height, robots, walls, lights, caps, regions, assignment,
                java.util.Collections.nCopies(robots.size(), RobotKind.DEFAULT));
    }

    /**
     * An arena without an assignment, its robots all Khepera Is.
     *
     * @param name    identifier of letters, digits, {@code _} and {@code -}
     * @param width   extent along x, mm
     * @param height  extent along y, mm
     * @param robots  start poses
     * @param walls   fixed walls
     * @param lights  fixed lamps
     * @param caps    movable bottle caps
     * @param regions named rectangles
     */
    public Arena(String name, double width, double height, List<Pose> robots, List<Wall> walls,
                 List<Light> lights, List<Cap> caps, List<Region> regions) {
        this(name, width, height, robots, walls, lights, caps, regions, Assignment.NONE);
    }

    /** @param a the assignment @return this arena with that assignment */
    public Arena withAssignment(Assignment a) {
        return new Arena(name, width, height, robots, walls, lights, caps, regions, a, robotKinds);
    }

    /** @param i a robot's index @return that robot's type */
    public RobotType robotType(int i) {
        return robotKinds.get(i).type();
    }

    /**
     * @param newRobots start poses for a copy of this arena
     * @return the robot kinds for them: these, cut or filled with the default where the count changed
     */
    public List<RobotKind> kindsFor(List<Pose> newRobots) {
        List<RobotKind> out =
                new java.util.ArrayList<>(robotKinds.subList(0, StrictMath.min(robotKinds.size(), newRobots.size())));
        while (out.size() < newRobots.size()) {
            out.add(RobotKind.DEFAULT);
        }
        return out;
    }

    /**
     * @param kind a robot type for the robots whose line names none ({@code --robot-file})
     * @return this arena with those robots of that type; the robots whose line names a type keep it
     */
    public Arena withDefaultRobot(RobotKind kind) {
        List<RobotKind> kinds = new java.util.ArrayList<>();
        for (RobotKind k : robotKinds) {
            kinds.add(k.isDefault() ? kind : k);
        }
        return new Arena(name, width, height, robots, walls, lights, caps, regions, assignment, kinds);
    }

    /** @return the widest robot's body radius, mm */
    public double widestRobotMm() {
        double r = 0;
        for (RobotKind k : robotKinds) {
            r = StrictMath.max(r, k.type().body().radiusMm());
        }
        return r;
    }

    /**
     * @param regionName a region's name
     * @return the region of that name, or empty if there is none
     */
    public Optional<Region> region(String regionName) {
        for (Region r : regions) {
            if (r.name().equals(regionName)) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }
}
