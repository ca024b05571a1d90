package assignment;

import static org.kheperasim.testing.KheperaAssertions.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.testing.Run;
import org.kheperasim.testing.RunReports;

/**
 * The course's tests, which students do not see: the course's CI copies this file into
 * src/test/java/assignment/ before running mvn test. Each test is worth points in the CI's configuration
 * (see ../README.md); the arena's score becomes points through the scoresAtLeast... tests, one per step.
 *
 * <p>Other seeds than the students' tests use: a controller must work on every run, not on one.
 */
@ExtendWith(RunReports.class)
class GradingTest {
    private static final Path CORRIDOR = Path.of("src/test/resources/corridor.arena");

    /** The arena's own time limit (30 s) and score: what khepera-sim run --arena corridor.arena prints. */
    private static Run corridor(long seed) {
        return Run.of(MyController.class).in(CORRIDOR).seed(seed).run();
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void runsWithoutFaultsAndNeverTouchesAWall(long seed) {
        assertThat(corridor(seed)).endedNormally().neverTouched(WALL);
    }

    @Test
    void scoresAtLeastHalfThePoints() {
        assertThat(corridor(31)).scoredAtLeast(50);
    }

    @Test
    void scoresAllThePoints() {
        assertThat(corridor(31)).scoredAtLeast(100);
    }

    @Test
    void reachesTheGoalWithinTwentyFiveSeconds() {
        assertThat(corridor(32)).entered("goal").before(seconds(25));
    }
}
