package org.kheperasim.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.kheperasim.sim.testkit.KitRegion;

/**
 * Assertions about a run, made by {@link KheperaAssertions#assertThat(Run)} (every robot of the run) or
 * {@link KheperaAssertions#assertThat(RobotRun)} (one robot). Each checks at once and returns an object to
 * chain the next check on; a failed check throws an {@link org.opentest4j.AssertionFailedError} whose
 * message says what was expected, what happened and at what simulated time, and where the run's trace was
 * saved (see {@link RunReports}).
 *
 * <p>With several robots, {@link #entered} is met when any robot entered the region (as an arena's
 * {@code task reach} counts it), and the others are checked for every robot.
 */
public sealed class RunAssert permits EntryAssert {
    final Run run;
    final List<RobotRun> robots;

    RunAssert(Run run, List<RobotRun> robots) {
        this.run = run;
        this.robots = List.copyOf(robots);
    }

    /**
     * Every controller ran to the end of the run, or returned by itself: none threw, hung, broke a rule or ran
     * out of memory. A run read from a trace fails it, since a trace does not record how a controller ended.
     *
     * @return this, for the next check
     */
    public RunAssert endedNormally() {
        for (RobotRun r : robots) {
            Ending e = r.ending();
            if (e.kind() == Ending.Kind.NOT_RECORDED) {
                throw Failure.of("A trace does not say how " + r.name() + "'s controller ended.")
                        .expected("the controller to run to the end of the run, or return by itself")
                        .happened("not known from a recorded run")
                        .hint("assert it on a run made by the test (Run.of(...).run()), or on run.rerun().again()")
                        .raise(run);
            }
            if (!e.normal()) {
                String at = e.at().map(t -> " at " + t).orElse("");
                String where = e.where().map(w -> " (" + w + ")").orElse("");
                throw Failure.of(r.name() + "'s controller " + verb(e.kind()) + at + where + ".")
                        .expected("the controller to run to the end of the run, or return by itself")
                        .happened(e.toString())
                        .raise(run);
            }
        }
        return this;
    }

    /**
     * No robot's body ever touched any of these.
     *
     * @param what what must not be touched, e.g. {@code WALL}; none given: anything at all
     * @return this, for the next check
     */
    public RunAssert neverTouched(Obstacle... what) {
        Set<Obstacle> kinds = what.length == 0 ? EnumSet.allOf(Obstacle.class) : EnumSet.copyOf(Arrays.asList(what));
        RobotRun first = null;
        List<Contact> bad = List.of();
        for (RobotRun r : robots) {
            List<Contact> its = r.contacts().stream().filter(c -> kinds.contains(c.what())).toList();
            if (!its.isEmpty() && (first == null || its.get(0).from().isBefore(bad.get(0).from()))) {
                first = r;
                bad = its;
            }
        }
        if (first != null) {
            Contact c = bad.get(0);
            String more = bad.size() == 1 ? ""
                    : "; " + bad.size() + " such contacts in all, the last " + bad.get(bad.size() - 1);
            throw Failure.of(first.name() + " touched " + c.what().described() + " at " + c.from() + ".")
                    .expected("never to touch " + things(kinds))
                    .happened("touched " + c + more)
                    .raise(run);
        }
        return this;
    }

    /**
     * A robot's centre entered the region (with several robots: any of them). Chain {@link EntryAssert#before}
     * to say by when.
     *
     * @param region a region's name, as in the arena file
     * @return the entry, to say by when
     * @throws IllegalArgumentException when the arena has no such region
     */
    public EntryAssert entered(String region) {
        KitRegion g = run.region(region);
        Optional<RobotRun> first = firstIn(region);
        if (first.isEmpty()) {
            Nearest n = nearest(g, run.duration());
            String who = robots.size() == 1 ? robots.get(0).name() + " never entered"
                    : "None of the " + robots.size() + " robots entered";
            throw Failure.of(who + " region '" + region + "'.")
                    .expected("to enter region '" + region + "' " + bounds(g))
                    .happened("it did not in the " + run.duration() + " the run lasted; " + n)
                    .raise(run);
        }
        RobotRun r = first.get();
        return new EntryAssert(run, robots, region, r, r.entered(region).orElseThrow());
    }

    /**
     * No robot's centre ever entered the region.
     *
     * @param region a region's name, as in the arena file
     * @return this, for the next check
     */
    public RunAssert neverEntered(String region) {
        run.region(region);
        Optional<RobotRun> in = firstIn(region);
        if (in.isPresent()) {
            RobotRun r = in.get();
            SimTime t = r.entered(region).orElseThrow();
            throw Failure.of(r.name() + " entered region '" + region + "' at " + t + ".")
                    .expected("never to enter region '" + region + "'")
                    .happened("its centre entered it at " + t + ", at " + r.poseAt(t))
                    .raise(run);
        }
        return this;
    }

    /**
     * Every robot's centre lies inside the region at the end of the run.
     *
     * @param region a region's name, as in the arena file
     * @return this, for the next check
     */
    public RunAssert endedIn(String region) {
        KitRegion g = run.region(region);
        for (RobotRun r : robots) {
            Pose p = r.finalPose();
            if (!g.contains(p.x(), p.y())) {
                throw Failure.of(r.name() + " did not end in region '" + region + "'.")
                        .expected("to be inside region '" + region + "' " + bounds(g) + " at the end, "
                                + run.duration())
                        .happened(String.format(Locale.ROOT, "it ended at %s, %.1f mm from the region", p,
                                RunShapes.distanceTo(p.x(), p.y(), g)))
                        .raise(run);
            }
        }
        return this;
    }

    /**
     * Every robot's centre ends within {@code mm} of a point.
     *
     * @param x the point, mm from the arena's left edge
     * @param y the point, mm from the arena's bottom edge
     * @param mm how near, mm
     * @return this, for the next check
     */
    public RunAssert endedNear(double x, double y, double mm) {
        for (RobotRun r : robots) {
            Pose p = r.finalPose();
            double d = p.distanceTo(x, y);
            if (!(d <= mm)) {
                throw Failure.of(String.format(Locale.ROOT, "%s ended %.1f mm from (%.1f, %.1f) mm.",
                        r.name(), d, x, y))
                        .expected(String.format(Locale.ROOT,
                                "to end within %.1f mm of (%.1f, %.1f) mm, at %s", mm, x, y,
                                run.duration()))
                        .happened("it ended at " + p)
                        .raise(run);
            }
        }
        return this;
    }

    /**
     * Every robot travelled at least this far (the length of its path).
     *
     * @param mm the distance, mm
     * @return this, for the next check
     */
    public RunAssert travelledAtLeast(double mm) {
        for (RobotRun r : robots) {
            if (!(r.distanceMm() >= mm)) {
                throw Failure.of(String.format(Locale.ROOT, "%s travelled only %.1f mm.", r.name(), r.distanceMm()))
                        .expected(String.format(Locale.ROOT, "to travel at least %.1f mm in %s", mm, run.duration()))
                        .happened(String.format(Locale.ROOT, "its path was %.1f mm long; it ended at %s",
                                r.distanceMm(), r.finalPose()))
                        .raise(run);
            }
        }
        return this;
    }

    /**
     * The run scored at least this many points on its arena's tasks (as {@code khepera-sim run} scores it).
     *
     * @param points the least score, in the arena's points
     * @return this, for the next check
     */
    public RunAssert scoredAtLeast(double points) {
        Score s = run.score();
        if (s.max() == 0) {
            throw Failure.of("The arena " + run.arena() + " sets no task, so the run has no score.")
                    .expected("a score of at least " + Score.number(points))
                    .happened("the arena file has no 'task' line")
                    .raise(run);
        }
        if (!(s.points() >= points)) {
            throw Failure.of("The run scored " + Score.number(s.points()) + " of " + Score.number(s.max())
                    + " points, less than " + Score.number(points) + ".")
                    .expected("a score of at least " + Score.number(points) + " of "
                            + Score.number(s.max()) + " points by "
                            + run.duration())
                    .happened("score " + s)
                    .raise(run);
        }
        return this;
    }

    /**
     * At least {@code caps} caps lie on the floor inside the region at the end of the run.
     *
     * @param caps how many, at least
     * @param region a region's name, as in the arena file
     * @return this, for the next check
     */
    public RunAssert delivered(int caps, String region) {
        int in = run.capsIn(region);
        if (in < caps) {
            List<String> moved = new ArrayList<>();
            run.caps().stream().filter(Cap::moved).forEach(c -> moved.add("cap " + c.id() + " first moved at "
                    + c.firstMoved().orElseThrow() + (c.heldAtEnd() >= 0 ? ", held at the end" : "")));
            throw Failure.of(in + " cap" + (in == 1 ? "" : "s") + " lie in region '" + region
                    + "' at the end, fewer than "
                    + caps + ".")
                    .expected("at least " + caps + " cap" + (caps == 1 ? "" : "s")
                            + " on the floor in region '" + region
                            + "' at " + run.duration())
                    .happened(in + " there; " + (moved.isEmpty() ? "no cap moved" : String.join("; ", moved)))
                    .raise(run);
        }
        return this;
    }


    /**
     * Made again from the same arena, controllers, seed and settings, the run gives the same trace, line for line
     * (what {@code khepera-sim verify} checks). It fails for a controller that reads something the simulator does
     * not control, or for a recording whose controller or arena changed since.
     *
     * @return this, for the next check
     */
    public RunAssert replaysIdentically() {
        Rerun again = run.rerun();
        if (!again.identical()) {
            Path saved = again.again().saveTo(TestRuns.folderNow().resolve("again"));
            throw Failure.of("The run came out differently when made again.")
                    .expected("the same trace: the same arena, controllers, seed and settings give the same run")
                    .happened(again.toString() + "; the run made again: " + RunSpec.shown(saved))
                    .hint("a controller must take everything it does from the robot's sensors and the simulated clock;"
                            + " a static field kept from an earlier run, or the order of a HashSet of objects without"
                            + " hashCode, differs between runs")
                    .raise(run);
        }
        return this;
    }

    private Optional<RobotRun> firstIn(String region) {
        RobotRun best = null;
        for (RobotRun r : robots) {
            Optional<SimTime> t = r.entered(region);
            if (t.isPresent() && (best == null || t.get().isBefore(best.entered(region).orElseThrow()))) {
                best = r;
            }
        }
        return Optional.ofNullable(best);
    }

    /**
     * How near the robots came to a region by a time.
     *
     * @param name who came nearest
     * @param mm how near, mm
     * @param at when
     * @param end where it ended
     */
    record Nearest(String name, double mm, SimTime at, Pose end) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%snearest %.1f mm from it at %s; ended at %s",
                    name.isEmpty() ? "" : name + " came ", mm, at, end);
        }
    }

    /** The robot of this assertion that came nearest the region up to {@code until}, and when. */
    Nearest nearest(KitRegion g, SimTime until) {
        Nearest best = null;
        for (RobotRun r : robots) {
            for (PathPoint p : r.path()) {
                if (p.time().isAfter(until)) {
                    break;
                }
                double d = RunShapes.distanceTo(p.x(), p.y(), g);
                if (best == null || d < best.mm()) {
                    best = new Nearest(robots.size() == 1 ? "" : r.name(), d, p.time(), r.finalPose());
                }
            }
        }
        return best;
    }

    static String bounds(KitRegion g) {
        return String.format(Locale.ROOT, "(x %.1f..%.1f mm, y %.1f..%.1f mm)", g.x1(), g.x2(), g.y1(), g.y2());
    }

    private static String things(Set<Obstacle> kinds) {
        if (kinds.size() == Obstacle.values().length) {
            return "anything (a wall, a lamp, another robot or a cap)";
        }
        List<String> words = kinds.stream().map(Obstacle::described).toList();
        return words.size() == 1 ? words.get(0)
                : String.join(", ", words.subList(0, words.size() - 1)) + " or " + words.get(words.size() - 1);
    }

    private static String verb(Ending.Kind kind) {
        return switch (kind) {
            case THREW -> "threw an exception";
            case HUNG -> "hung (stopped making API calls)";
            case BROKE_A_RULE -> "broke a rule of the simulator";
            case OUT_OF_MEMORY -> "ran out of memory";
            default -> "ended";
        };
    }
}
