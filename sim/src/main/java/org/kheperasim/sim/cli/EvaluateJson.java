package org.kheperasim.sim.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.kheperasim.api.Parameters;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.eval.Job;
import org.kheperasim.sim.eval.Outcome;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.grade.JsonValues;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.Score;

/** The JSON lines of {@code evaluate}: a job read from one, an outcome written as one, shard outputs joined. */
final class EvaluateJson {
    /** The largest shard output {@code --join} reads, bytes (an outcome line is about 1 KB). */
    static final long MAX_JOIN_BYTES = 256L << 20;

    private EvaluateJson() {
    }

    /**
     * @param index the job's line, from 0
     * @param line one JSON object
     * @param controller the controller of a job that names none, or null
     * @param arena the arena of a job that names none, or null
     * @param seconds the simulated time of a job that says none
     * @return the job
     * @throws IllegalArgumentException naming what is wrong and the fix
     */
    static Job job(long index, String line, String controller, String arena, double seconds) {
        Object v = JsonValues.parse(line);
        if (!(v instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException("a job is a JSON object, e.g. {\"controller\": \"StepBraitenberg\","
                    + " \"arena\": \"lab\"}");
        }
        for (Object key : m.keySet()) {
            if (!List.of("id", "controller", "arena", "seed", "seconds", "parameters", "settings", "trace")
                    .contains(key)) {
                throw new IllegalArgumentException("unknown field \"" + key
                        + "\"; a job has id, controller, arena, seed,"
                        + " seconds, parameters, settings and trace");
            }
        }
        String c = text(m, "controller", controller);
        String a = text(m, "arena", arena);
        if (c == null || a == null) {
            throw new IllegalArgumentException("no " + (c == null ? "controller" : "arena") + ": give it in the job or"
                    + " with --" + (c == null ? "controller" : "arena"));
        }
        long seed = m.containsKey("seed") ? whole(m.get("seed"), "seed") : index + 1;
        double s = m.containsKey("seconds") ? number(m.get("seconds"), "seconds") : seconds;
        if (!(s > 0 && s <= Job.MAX_SECONDS)) {
            throw new IllegalArgumentException("\"seconds\": " + m.get("seconds")
                    + " is out of range; give a simulated time"
                    + " greater than 0 and at most " + (long) Job.MAX_SECONDS + ", e.g. 60");
        }
        Object t = m.get("trace");
        return new Job(index, text(m, "id", ""), c, a, seed, s, parameters(m.get("parameters")),
                settings(m.get("settings")),
                t == null ? null : Path.of(string(t, "trace")));
    }

    /** @return a job line's id, for the error of a line that is not a job; "" when there is none */
    static String idOf(String line) {
        try {
            if (JsonValues.parse(line) instanceof Map<?, ?> m && m.get("id") instanceof String id) {
                return id;
            }
        } catch (IllegalArgumentException e) {
            // not JSON: no id
        }
        return "";
    }

    private static String text(Map<?, ?> m, String key, String otherwise) {
        Object v = m.get(key);
        return v == null ? otherwise : string(v, key);
    }

    private static String string(Object v, String key) {
        if (!(v instanceof String s)) {
            throw new IllegalArgumentException("\"" + key + "\" must be a string, not " + v);
        }
        return s;
    }

    private static double number(Object v, String key) {
        if (!(v instanceof Double d) || !Double.isFinite(d)) {
            throw new IllegalArgumentException("\"" + key + "\" must be a number, not " + v);
        }
        return d;
    }

    private static long whole(Object v, String key) {
        double d = number(v, key);
        if (d != StrictMath.rint(d) || StrictMath.abs(d) > 9.0e15) {
            throw new IllegalArgumentException("\"" + key + "\" must be a whole number, not " + v);
        }
        return (long) d;
    }

    private static Parameters parameters(Object v) {
        if (v == null) {
            return Parameters.NONE;
        }
        if (!(v instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException(
                    "\"parameters\" must be an object of names and numbers or arrays of numbers,"
                    + " e.g. {\"weights\": [0.4, 0.8], \"gain\": 2}");
        }
        Map<String, double[]> out = new LinkedHashMap<>();
        for (Map.Entry<?, ?> e : m.entrySet()) {
            String name = (String) e.getKey();
            if (e.getValue() instanceof List<?> list) {
                double[] d = new double[list.size()];
                for (int i = 0; i < d.length; i++) {
                    d[i] = number(list.get(i), "parameters." + name);
                }
                out.put(name, d);
            } else {
                out.put(name, new double[] {number(e.getValue(), "parameters." + name)});
            }
        }
        return Parameters.of(out);
    }

    private static Map<String, String> settings(Object v) {
        if (v == null) {
            return Map.of();
        }
        if (!(v instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException("\"settings\" must be an object of setting names and values, e.g."
                    + " {\"noise.reading\": \"0.5\"} (khepera-sim settings lists them)");
        }
        Map<String, String> out = new TreeMap<>();
        for (Map.Entry<?, ?> e : m.entrySet()) {
            Object val = e.getValue();
            out.put((String) e.getKey(), val instanceof Double d && d == StrictMath.rint(d) && StrictMath.abs(d) < 1e15
                    ? Long.toString(d.longValue()) : String.valueOf(val));
        }
        return out;
    }

    /** @return the outcome of a job as one JSON line: only what the job decides (no wall times) */
    static String outcome(Outcome o) {
        Json j = new Json().begin().put("index", o.job().index()).put("id", o.job().id());
        if (o.error() != null) {
            return j.put("status", "error").put("error", o.error()).end().toString();
        }
        RunResult r = o.result();
        j.put("status", o.ok() ? "ok" : "failed").put("controller", r.controller()).put("arena", r.arena())
                .put("seed", r.seed()).put("simulatedSeconds", r.simulatedSeconds());
        if (!o.job().parameters().isEmpty()) {
            j.put("parameters", o.job().parameters().toString());
        }
        Score score = o.score();
        if (score != null) {
            j.beginObject("score").put("points", score.points()).put("max", score.max())
                    .put("percent", score.percent());
            j.beginArray("tasks");
            for (Score.Part p : score.parts()) {
                j.element().put("task", p.task()).put("points", p.points()).put("max", p.max())
                        .put("detail", p.detail()).end();
            }
            j.endArray().end();
        }
        j.beginArray("robots");
        for (RunResult.RobotResult rr : r.robots()) {
            j.element().put("name", rr.name()).put("x", rr.x()).put("y", rr.y()).put("headingDeg", rr.headingDeg())
                    .put("distanceMm", rr.distanceMm()).put("collisions", rr.collisions())
                    .put("visitedPercent", rr.visitedPercent()).put("regionsEntered", rr.regionsEntered())
                    .put("controllerStatus", rr.status().name().toLowerCase(Locale.ROOT))
                    .put("failure", rr.failure()).end();
        }
        j.endArray();
        if (o.job().trace() != null) {
            j.put("trace", o.job().trace().toString()).put("traceSha256", r.traceSha256());
        }
        return j.end().toString();
    }

    /** @return the outcome line of a job line that could not be read */
    static String error(long index, String id, String message) {
        return new Json().begin().put("index", index).put("id", id).put("status", "error").put("error", message).end()
                .toString();
    }

    /**
     * Join the outputs of {@code --shard} slices into the jobs' order: the lines one machine's
     * {@code --ordered} run writes.
     *
     * @return the exit status: bad input when a line is not an outcome or two name one job
     */
    static int join(List<Path> files, PrintStream sink) throws IOException {
        TreeMap<Long, String> lines = new TreeMap<>();
        boolean anyFailed = false;
        for (Path f : files) {
            List<String> all = TextFiles.readUtf8(f, MAX_JOIN_BYTES, "evaluate output",
                    (line, what) -> new InputFileException(f.toString(), line, what)).lines().toList();
            for (int i = 0; i < all.size(); i++) {
                String line = all.get(i);
                if (line.isBlank()) {
                    continue;
                }
                Object v;
                try {
                    v = JsonValues.parse(line);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException(f + ":" + (i + 1) + ": not an outcome of evaluate ("
                            + e.getMessage() + ")");
                }
                if (!(v instanceof Map<?, ?> m) || !(m.get("index") instanceof Double d)) {
                    throw new IllegalArgumentException(f + ":" + (i + 1)
                            + ": not an outcome of evaluate (no \"index\")");
                }
                if (lines.put(d.longValue(), line) != null) {
                    throw new IllegalArgumentException(f + ":" + (i + 1) + ": job " + d.longValue()
                            + " is in two outputs;"
                            + " join the outputs of one evaluation's slices");
                }
                anyFailed |= !"ok".equals(m.get("status"));
            }
        }
        lines.values().forEach(sink::println);
        sink.flush();
        return anyFailed ? ExitCodes.FAILED : ExitCodes.OK;
    }
}
