package org.kheperasim.sim;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

/**
 * No two packages of the simulator depend on each other, directly or round a longer loop: each
 * package is its own slice, a subpackage too (a package and its subpackage must not use each other
 * both ways: the shared piece goes into the lower one, or an interface of the lower one is
 * implemented in the upper one). The engine's own packages too: the engine on top, then link, sensing,
 * body, space, view, model, robot and noise, each using only those below it. The other modules check their own packages (api, robot-link,
 * testing); Maven's module order keeps the modules themselves from depending on each other both ways.
 */
class NoPackageCyclesTest {
    @Test
    void theSimulatorsPackagesAreFreeOfCycles() {
        JavaClasses sim = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.sim");
        slices().matching("org.kheperasim.(**)")
                .should().beFreeOfCycles()
                .because("a package that uses its user cannot be understood, tested or moved without it;"
                        + " break the cycle by moving the shared type down or inverting an interface,"
                        + " never by suppressing it")
                .check(sim);
    }
}
