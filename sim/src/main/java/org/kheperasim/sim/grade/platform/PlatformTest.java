package org.kheperasim.sim.grade.platform;

/**
 * One test as a learning platform shows it: a run (an arena and a seed) of a grading, or a test case of
 * a JUnit report. Its text is shown to a person and has its control characters escaped already.
 *
 * @param name    what the student reads, e.g. {@code maze, seed 3}
 * @param number  its number, e.g. {@code 1.3} (arena 1, seed 3)
 * @param score   points earned
 * @param max     points available
 * @param passed  true when it went to its end without a fault (a run {@code ok}, a test case that passed)
 * @param status  the grading's word for how it ended ({@code ok}, {@code threw}, ...; for JUnit {@code passed},
 *                {@code failed}, {@code error}, {@code skipped})
 * @param output  how it ended, one line or several: the score's details, the failure with the student's file and line
 * @param hidden  true when the student must not see it (a hidden arena, the instructor's hidden tests)
 * @param picture the trajectory picture, relative to the report folder, or empty
 * @param group   the arena (or the JUnit class) it belongs to, for a leaderboard
 */
public record PlatformTest(String name, String number, double score, double max, boolean passed,
        String status, String output,
        boolean hidden, String picture, String group) {
    /** Replaces nulls by empty text. */
    public PlatformTest {
        output = output == null ? "" : output;
        picture = picture == null ? "" : picture;
        group = group == null ? "" : group;
    }

    /**
     * @return this test as a platform without a visibility of its own shows it to the student: a hidden test
     *     keeps its points, and loses its name, how it ended and its picture
     */
    public PlatformTest masked() {
        if (!hidden) {
            return this;
        }
        return new PlatformTest("hidden test " + number, number, score, max, passed, passed ? "passed" : "failed",
                "a hidden test of the course: " + (passed ? "passed" : "not passed"), true, "", "");
    }
}
