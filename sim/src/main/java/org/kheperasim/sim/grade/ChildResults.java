package org.kheperasim.sim.grade;

import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Turns what a child run left (its exit status, the {@code run --json} line, the tail of its
 * standard error, whether it was killed at the wall-clock limit) into a {@link RunRecord}.
 */
final class ChildResults {
    private static final int MAX_DETAIL = 300;

    private ChildResults() {
    }

    static RunRecord record(GradePlan.Job job, String controller, boolean killed, double wallLimit, int exit,
            String out, String err) {
        Map<String, Object> json = lastJsonLine(out);
        if (json == null) {
            return noResult(job, controller, killed, wallLimit, exit, err);
        }
        RunStatus status = RunStatus.OK;
        String failure = null;
        Object robots = json.get("robots");
        if (robots instanceof List<?> list) {
            for (Object o : list) {
                if (o instanceof Map<?, ?> robot) {
                    RunStatus s = ofController(String.valueOf(robot.get("controllerStatus")));
                    if (s != RunStatus.OK) {
                        status = s;
                        // What it threw; for the other faults the run's error line, read below without
                        // what depends on the machine (the JSON's text keeps it).
                        failure = s != RunStatus.THREW || robot.get("failure") == null ? null : String.valueOf(robot.get("failure"));
                        break;
                    }
                }
            }
        }
        double points = 0;
        double max = 0;
        double percent = 0;
        StringBuilder detail = new StringBuilder();
        if (json.get("score") instanceof Map<?, ?> score) {
            points = number(score.get("points"));
            max = number(score.get("max"));
            percent = number(score.get("percent"));
            if (score.get("tasks") instanceof List<?> tasks) {
                for (Object t : tasks) {
                    if (t instanceof Map<?, ?> task) {
                        detail.append(detail.length() > 0 ? "; " : "")
                                .append(String.valueOf(task.get("task")).replaceFirst("^task ", "")).append(": ")
                                .append(task.get("detail"));
                    }
                }
            }
        }
        if (status == RunStatus.EXCEEDED_MEMORY) {
            // The heap watch or an OutOfMemoryError, depending on the collector's timing: one text for both.
            failure = "controller " + controller + " allocated without bound and was stopped at the run's heap limit";
        } else if (failure == null && status != RunStatus.OK) {
            failure = fault(err);
        }
        if (failure != null) {
            detail.insert(0, shorten(failure) + (detail.length() > 0 ? " | " : ""));
        }
        return new RunRecord(job.student(), job.arena(), job.seed(), status, points, max, percent,
                number(json.get("simulatedSeconds")), controller, detail.toString(), "");
    }

    private static RunRecord noResult(GradePlan.Job job, String controller, boolean killed, double wallLimit, int exit,
            String err) {
        RunStatus status;
        String detail;
        if (killed) {
            status = RunStatus.HUNG;
            detail = String.format(Locale.ROOT, "no result within the wall-clock limit of %.0f s; the run was killed",
                    wallLimit);
        } else if (err.contains("OutOfMemoryError")) {
            status = RunStatus.EXCEEDED_MEMORY;
            detail = "the run's JVM ran out of heap (exit status " + exit + ")";
        } else if (err.contains(" was refused: ")) {
            status = RunStatus.BROKE_RULE;
            detail = lastLine(err, " was refused: ");
        } else {
            status = RunStatus.ERROR;
            detail = "exit status " + exit + ": " + lastLine(err, "");
        }
        return new RunRecord(job.student(), job.arena(), job.seed(), status, 0, 0, 0, 0, controller, shorten(detail), "");
    }

    /**
     * The simulator's report of a fault from the child's standard error ({@code [  1.000 s] ERROR Name: controller
     * Name (Class) called System.exit(3); the controller was stopped ...}), without what depends on the machine
     * (the heap's size and fill).
     */
    static String fault(String err) {
        for (String line : err.split("\\R")) {
            int e = line.indexOf("] ERROR ");
            int colon = e < 0 ? -1 : line.indexOf(": ", e);
            if (colon > 0 && line.indexOf("controller ", colon) == colon + 2) {
                String msg = line.substring(colon + 2);
                int cut = msg.indexOf("; the controller was stopped");
                msg = cut > 0 ? msg.substring(0, cut) : msg;
                return msg.replaceAll("\\s*\\([^()]*\\bMB\\b[^()]*\\)", "");
            }
        }
        return null;
    }

    static RunStatus ofController(String s) {
        return switch (s) {
            case "failed" -> RunStatus.THREW;
            case "hung" -> RunStatus.HUNG;
            case "broke_rule" -> RunStatus.BROKE_RULE;
            case "exceeded_memory" -> RunStatus.EXCEEDED_MEMORY;
            default -> RunStatus.OK; // finished, stopped, running (at the end), not_started
        };
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> lastJsonLine(String out) {
        String[] lines = out.split("\\R");
        for (int i = lines.length - 1; i >= 0; i--) {
            String l = lines[i].strip();
            if (l.startsWith("{")) {
                try {
                    return JsonValues.parse(l) instanceof Map<?, ?> m ? (Map<String, Object>) m : null;
                } catch (IllegalArgumentException e) {
                    return null;
                }
            }
        }
        return null;
    }

    private static String lastLine(String text, String containing) {
        String[] lines = text.split("\\R");
        for (int i = lines.length - 1; i >= 0; i--) {
            String l = lines[i].strip();
            if (!l.isEmpty() && l.contains(containing) && !l.startsWith("at ")) {
                return l;
            }
        }
        return "(no message)";
    }

    private static double number(Object o) {
        return o instanceof Number n ? n.doubleValue() : 0;
    }

    private static String shorten(String s) {
        String one = s.replaceAll("\\s+", " ").strip();
        return one.length() <= MAX_DETAIL ? one : one.substring(0, MAX_DETAIL - 3) + "...";
    }
}
