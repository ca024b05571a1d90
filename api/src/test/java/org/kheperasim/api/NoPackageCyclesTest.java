package org.kheperasim.api;

import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.library.dependencies.SliceRule;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * No two packages of the api module depend on each other both ways, each package its own slice;
 * but for one cycle that is left, {@code api} and {@code api.spi}, which this test names and watches.
 *
 * <p>The student API's objects ({@code CurrentRobotState}, {@code Motor}, {@code Sensor}, ...) delegate
 * to the backend's {@code spi.RobotPort}, and {@code Controller}'s constructor with no parameters reads
 * {@code spi.ControllerBinding}; the port speaks in the student API's values ({@code ArmPosition},
 * {@code GripperState}, {@code SensorMount}, {@code Parameters}) and the controller contract
 * ({@code spi.Controllers}, {@code StepRunner}, {@code ControllerStyle}) makes student controllers. The
 * port cannot move into {@code org.kheperasim.api} (controllers may use everything there, and the port
 * gives a backend's ground truth), nor the values into {@code api.spi} (students name them); breaking
 * the cycle means a port that speaks in its own types, which is a change of the port itself.
 */
class NoPackageCyclesTest {
    private static JavaClasses api;

    @BeforeAll
    static void importClasses() {
        api = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.api");
    }

    private static SliceRule rule() {
        return slices().matching("org.kheperasim.(**)").should().beFreeOfCycles()
                .because("a package that uses its user cannot be understood, tested or moved without it;"
                        + " break the cycle by moving the shared type down or inverting an interface");
    }

    @Test
    void theApisPackagesAreFreeOfCyclesButTheOneLeft() {
        // The cycle left: the student API's use of its port (api -> api.spi), see the class comment.
        rule().ignoreDependency(resideInAPackage("org.kheperasim.api"), resideInAPackage("org.kheperasim.api.spi"))
                .check(api);
    }

    @Test
    void theCycleLeftIsStillThere() {
        assertThrows(AssertionError.class, () -> rule().check(api), "api and api.spi no longer depend on each"
                + " other both ways: drop the ignored dependency of theApisPackagesAreFreeOfCyclesButTheOneLeft"
                + " and this test");
    }
}
