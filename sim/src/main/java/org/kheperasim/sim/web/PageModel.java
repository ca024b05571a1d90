package org.kheperasim.sim.web;

import java.util.List;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.task.Score;

/**
 * The page's description of a run, as one JSON object: what it is, the arena (each version, when
 * edited during the run), the robot model the drawing needs (sensor places, arm range), how the
 * samples were packed, the score at each change, the failures. The samples themselves travel apart,
 * packed by {@link TapeEncoder}.
 */
final class PageModel {
    /**
     * What the page says about its run.
     *
     * @param title    the heading
     * @param source   the file it was made from, or empty
     * @param notes    what the reader had to say (an arena found by name, a file cut short)
     * @param failures the controllers that failed, with their times (NaN: not known)
     */
    record About(String title, String source, List<String> notes, List<RunOutcome.Failure> failures) {
    }

    private PageModel() {
    }

    static String json(About about, RunTape tape, TapeEncoder.Encoded packed, List<ScoreTimeline.Moment> scores,
            boolean coverageAtEnd) {
        PageJson j = new PageJson().begin();
        j.put("format", 1).put("title", about.title()).put("source", about.source());
        j.array("notes");
        about.notes().forEach(j::value);
        j.endArray();
        List<RunTape.Track> robots = tape.robots();
        j.put("endMs", tape.endMs()).put("sampleMs", sampleMs(tape)).put("poseStride", packed.poseStride())
                .put("sensorStride", packed.sensorStride()).put("rawBytes", packed.rawBytes())
                .put("robotsInRun", tape.robotsInRun()).put("capMoves", tape.caps().size());
        j.array("robots");
        for (int i = 0; i < robots.size(); i++) {
            j.begin().put("name", robots.get(i).name).put("n", packed.kept()[i])
                    .put("sensors", robots.get(i).sensors != null);
            RobotType type = robots.get(i).type;
            if (!type.equals(RobotTypes.KHEPERA1)) {
                // Another robot than the model's: its own body and sensors (a Khepera's page is as it was).
                j.put("radius", type.body().radiusMm()).array("mounts");
                for (RobotType.Sensor s : type.sensors()) {
                    j.array().value(s.xMm()).value(s.yMm()).value(s.headingDeg()).endArray();
                }
                j.endArray();
            }
            j.end();
        }
        j.endArray();
        j.array("arenas");
        for (RunTape.ArenaVersion v : tape.arenas()) {
            arena(j, v.ms(), v.arena());
        }
        j.endArray();
        j.array("scores");
        for (ScoreTimeline.Moment m : scores) {
            Score s = m.score();
            j.begin().put("t", m.ms()).put("points", Score.number(s.points())).put("max", Score.number(s.max()))
                    .put("percent", s.percent()).put("pending", m.pending());
            j.array("parts");
            for (Score.Part p : s.parts()) {
                boolean cover = p.task().startsWith("task cover");
                j.array().value(p.task().replaceFirst("^task ", "")).value(cover && m.pending() ? "" : p.detail())
                        .value(Score.number(p.points())).value(Score.number(p.max())).endArray();
            }
            j.endArray().end();
        }
        j.endArray();
        j.put("coverageAtEnd", coverageAtEnd);
        j.array("failures");
        for (RunOutcome.Failure f : about.failures()) {
            j.begin().put("robot", f.robot()).put("t", f.seconds() * 1000).put("status", f.status())
                    .put("message", f.message()).end();
        }
        j.endArray();
        model(j);
        return j.end().toString();
    }

    /** The sample period, ms: the most common gap between the first robot's samples. */
    static long sampleMs(RunTape tape) {
        if (tape.robots().isEmpty() || tape.robots().get(0).size() < 2) {
            return 0;
        }
        IntList t = tape.robots().get(0).t;
        java.util.Map<Integer, Integer> gaps = new java.util.HashMap<>();
        for (int i = 1; i < StrictMath.min(t.size(), 2000); i++) {
            gaps.merge(t.get(i) - t.get(i - 1), 1, Integer::sum);
        }
        return gaps.entrySet().stream().max(java.util.Map.Entry.comparingByValue())
                .map(java.util.Map.Entry::getKey).orElse(0);
    }

    private static void arena(PageJson j, long ms, Arena a) {
        j.begin().put("t", ms).put("name", a.name()).put("w", a.width()).put("h", a.height());
        j.array("walls");
        for (Wall w : a.walls()) {
            j.array().value(w.x1()).value(w.y1()).value(w.x2()).value(w.y2()).value(w.thickness()).endArray();
        }
        j.endArray().array("lights");
        for (Light l : a.lights()) {
            j.array().value(l.x()).value(l.y()).value(l.radius()).value(l.range()).value(l.intensity())
                    .value(l.isDirectional() ? l.directionDeg() : Double.NaN).value(l.spreadDeg()).endArray();
        }
        j.endArray().array("regions");
        for (Region r : a.regions()) {
            j.array().value(r.name()).value(r.x1()).value(r.y1()).value(r.x2()).value(r.y2()).endArray();
        }
        j.endArray().array("caps");
        for (Cap c : a.caps()) {
            j.array().value(c.x()).value(c.y()).value(c.radius()).endArray();
        }
        j.endArray().array("robots");
        for (Pose p : a.robots()) {
            j.array().value(p.x()).value(p.y()).value(p.headingDeg()).endArray();
        }
        j.endArray().end();
    }

    /** What the drawing needs of the robot: the same numbers the simulator uses, not copies in the page. */
    private static void model(PageJson j) {
        j.begin("model").put("robotRadius", RobotTypes.KHEPERA1.body().radiusMm()).put("armUp", GripperTurret.ARM_UP)
                .put("armDown", GripperTurret.ARM_DOWN).put("capRadius", Cap.DEFAULT_RADIUS);
        j.array("sensors");
        for (RobotType.Sensor s : RobotTypes.KHEPERA1.sensors()) {
            j.array().value(s.xMm()).value(s.yMm()).value(s.headingDeg()).endArray();
        }
        j.endArray().array("contacts");
        for (Contact c : Contact.values()) {
            j.value(c.name().toLowerCase(java.util.Locale.ROOT).replace('_', '-'));
        }
        j.endArray().array("fingers");
        for (GripperState g : GripperState.values()) {
            j.value(g.name().toLowerCase(java.util.Locale.ROOT));
        }
        j.endArray();
        j.put("fingersOpen", GripperState.OPEN.ordinal());
        j.end();
    }
}
