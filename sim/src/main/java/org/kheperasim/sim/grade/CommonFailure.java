package org.kheperasim.sim.grade;

import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * A grading in which every run failed for one reason is most likely the grader's failure, not the
 * class's (the simulator's classes not found by the runs, a wall-clock limit too short for the machine,
 * the wrong submissions folder): said in one line naming the reason and the likely fix, and {@code grade}
 * exits non-zero, so that a class of zeros is never published unnoticed. Reasons are compared with the
 * student's and the controller's names taken out. A single student's runs failing alike are that
 * student's, unless the reason is the grader's own ({@link RunStatus#ERROR}).
 */
public final class CommonFailure {
    private CommonFailure() {
    }

    /**
     * @param runs a report's runs
     * @return the line to print, without the tool's prefix; empty when some run did not fail, or runs failed
     *     for different reasons
     */
    public static Optional<String> of(List<RunRecord> runs) {
        if (runs.isEmpty()) {
            return Optional.empty();
        }
        Set<String> students = new HashSet<>();
        String reason = null;
        for (RunRecord r : runs) {
            if (r.status() == RunStatus.OK) {
                return Optional.empty();
            }
            String own = r.status().label() + ": " + anonymous(r);
            if (reason != null && !reason.equals(own)) {
                return Optional.empty();
            }
            reason = own;
            students.add(r.student());
        }
        RunStatus status = runs.get(0).status();
        if (students.size() < 2 && status != RunStatus.ERROR) {
            return Optional.empty();
        }
        String shown = reason.length() > 240 ? reason.substring(0, 237) + "..." : reason;
        return Optional.of(String.format(Locale.ROOT, "every run of this grading failed the same way (%d runs of %d"
                + " students): %s; %s", runs.size(), students.size(), shown, fix(status, reason)));
    }

    private static String anonymous(RunRecord r) {
        String d = r.detail();
        if (!r.controller().isEmpty()) {
            d = d.replace(r.controller(), "<controller>");
            String simple = r.controller().substring(r.controller().lastIndexOf('.') + 1);
            d = d.replace(simple, "<controller>");
        }
        return d.replace(r.student(), "<student>");
    }

    private static String fix(RunStatus status, String reason) {
        return switch (status) {
            case ERROR -> reason.contains("ClassNotFoundException") || reason.contains("NoClassDefFoundError")
                    ? "the runs' JVMs did not find the simulator's classes: grade with the jar that mvn package builds"
                            + " (java -jar sim/target/khepera-sim.jar grade ...) and report this"
                    : "the runs could not be made on this machine: check the Java runtime, --heap-mb and the sandbox"
                            + " (docs/grading.md, \"The sandbox\"); no student's code fails everyone's runs alike";
            case HUNG -> "the runs took longer than the machine allows: raise --wall-limit, or give fewer --jobs";
            case EXCEEDED_MEMORY -> "raise --heap-mb";
            case NOTHING_HANDED_IN, COMPILE_FAILED -> "check --submissions: it must hold one folder per student with"
                    + " the student's .java or .class files";
            case TAMPERED -> "the grader's replay disagrees with every run: a bug of the grader, please report it"
                    + " (grade again with --keep-traces to keep the command logs)";
            default -> "check the arenas and --seconds: every controller fails in them alike";
        };
    }
}
