package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The JVMs grade starts (each run's own, and a warm worker's, which are given the same options) map
 * the jar's class-data archive when it has one, and a box shows them that file; without one, their
 * command lines name none.
 */
class ChildArchiveTest {
    private static final ChildRun.Limits LIMITS = new ChildRun.Limits(128, 60, 5, 5.0, Grader.SAMPLE_MILLIS, 1, true,
            false);
    private static final Submission SUB = new Submission("alice", Path.of("/subs/alice"), "Explorer", null);

    @Test
    void anArchiveReachesTheCommandLineBeforeTheClasspathAndTheBoxShowsIt() {
        Path archive = Path.of("/opt/khepera/khepera-sim.jsa");
        List<String> java = ChildRun.jvmOptions(LIMITS, Optional.of(archive));
        int flag = java.indexOf("-XX:SharedArchiveFile=" + archive);
        assertTrue(flag >= 0, java.toString());
        assertTrue(flag < java.indexOf("-cp"), "a JVM option, before the classpath and the main class: " + java);
        assertTrue(java.contains("-Xshare:auto"), java.toString());
        assertTrue(ChildRun.boxed(SUB, List.of("lab"), Optional.of(archive)).contains(archive));
    }

    @Test
    void withoutAnArchiveTheCommandLineNamesNone() {
        List<String> java = ChildRun.jvmOptions(LIMITS, Optional.empty());
        assertFalse(java.stream().anyMatch(o -> o.contains("SharedArchive") || o.startsWith("-Xshare")),
                java.toString());
        assertEquals(ChildRun.boxed(SUB, List.of("lab")), ChildRun.boxed(SUB, List.of("lab"), Optional.empty()));
        // The tests' own classes are folders, not a jar: no archive, the one-argument forms agree.
        assertEquals(java, ChildRun.jvmOptions(LIMITS));
    }
}
