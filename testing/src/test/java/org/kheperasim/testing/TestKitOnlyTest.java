package org.kheperasim.testing;

import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import org.junit.jupiter.api.Test;

/**
 * The testing library reaches the simulator through one facade, {@code org.kheperasim.sim.testkit}, and
 * the student API: none of the simulator's inner packages (engine, arena, run, host, trace, ...), so they
 * can move without breaking the library that courses' tests are written against.
 */
class TestKitOnlyTest {
    private static final DescribedPredicate<com.tngtech.archunit.core.domain.JavaClass> SIMULATOR_INSIDE =
            resideInAPackage("org.kheperasim..")
                    .and(DescribedPredicate.not(resideInAnyPackage("org.kheperasim.sim.testkit..",
                            "org.kheperasim.api..", "org.kheperasim.testing..")))
                    .as("the simulator's classes outside its test kit");

    private static final ArchRule THROUGH_THE_TEST_KIT = noClasses().should().dependOnClassesThat(SIMULATOR_INSIDE)
            .because("the testing module goes through org.kheperasim.sim.testkit (issue 36)");

    @Test
    void theMainCodeUsesTheSimulatorOnlyThroughTheTestKit() {
        JavaClasses main = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.testing");
        assertTrue(main.size() > 20, "the library's classes were found: " + main.size());
        THROUGH_THE_TEST_KIT.check(main);
    }

    @Test
    void theRuleCatchesAClassThatReachesInside() {
        // This module's tests may use the simulator's inside (to build recordings): the rule sees it there.
        JavaClasses test = new ClassFileImporter().importClasses(RecordedRunTest.class);
        assertTrue(THROUGH_THE_TEST_KIT.evaluate(test).hasViolation());
    }
}
