package org.kheperasim.sim.grade.platform;

import java.util.List;

/**
 * One submission's result, as every platform's writer takes it.
 *
 * @param student     the submission (its folder's name)
 * @param tests       its tests, in the grading's order
 * @param gradable    false when the submission could not be graded at all (it does not compile, holds
 *                    nothing, or its controller was refused at load): a platform that knows "not gradable"
 *                    says so instead of a zero
 * @param problem     why it is not gradable, one line (empty when it is)
 * @param leaderboard the values for a leaderboard (visible arenas' mean percent), in order
 * @param summary     a line for the whole submission
 */
public record PlatformResult(String student, List<PlatformTest> tests, boolean gradable, String problem,
        List<Leader> leaderboard, String summary) {
    /** Copies the lists. */
    public PlatformResult {
        tests = List.copyOf(tests);
        leaderboard = List.copyOf(leaderboard);
        problem = problem == null ? "" : problem;
    }

    /**
     * One leaderboard column.
     *
     * @param name  its name, e.g. {@code maze mean %}
     * @param value the value
     */
    public record Leader(String name, double value) {
    }

    /** @return the points earned */
    public double score() {
        return tests.stream().mapToDouble(PlatformTest::score).sum();
    }

    /** @return the points available */
    public double max() {
        return tests.stream().mapToDouble(PlatformTest::max).sum();
    }
}
