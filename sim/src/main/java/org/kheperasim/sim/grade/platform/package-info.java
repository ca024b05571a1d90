/**
 * A grading's results in the learning platforms' own formats ({@code grade --format}): Gradescope's
 * {@code results.json}, PrairieLearn's external grading results, GitHub Classroom's runner result and
 * CodeGrade's points line, one writer each, all from one {@link org.kheperasim.sim.grade.platform.PlatformResult}
 * per submission ({@link org.kheperasim.sim.grade.platform.GradingTests} from a grade report,
 * {@link org.kheperasim.sim.grade.platform.JunitReports} from JUnit XML). See docs/autograding.md.
 */
package org.kheperasim.sim.grade.platform;
