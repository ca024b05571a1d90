package assignment;

import static org.kheperasim.testing.KheperaAssertions.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kheperasim.testing.Run;
import org.kheperasim.testing.RunReports;

/**
 * Your controller in the simulator: each test runs it, headless and far faster than real time, and checks
 * what the robot did. A failing test's run is saved under target/kheperasim-runs/ to watch in the window.
 */
@ExtendWith(RunReports.class)
class MyControllerTest {

    /** In the bundled empty lab, for two simulated minutes, the robot never touches a wall. */
    @Test
    void neverTouchesAWallInTheLab() {
        Run run = Run.of(MyController.class).in("lab").seconds(120).seed(1).run();
        assertThat(run).endedNormally().neverTouched(WALL);
    }

    /** In the assignment's corridor (an arena file of this project), the robot reaches the goal within 30 seconds. */
    @Test
    void reachesTheGoalWithinHalfAMinute() {
        Run run = Run.of(MyController.class).in(Path.of("src/test/resources/corridor.arena")).seconds(60).seed(1).run();
        assertThat(run).endedNormally().entered("goal").before(seconds(30));
    }
}
