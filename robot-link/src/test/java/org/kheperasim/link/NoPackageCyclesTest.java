package org.kheperasim.link;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

/**
 * No two packages of robot-link depend on each other, directly or round a longer loop: each package
 * is its own slice, a subpackage too ({@code protocol} and {@code protocol.dialect} must not use each
 * other both ways). The simulator checks its own packages in its {@code NoPackageCyclesTest}.
 */
class NoPackageCyclesTest {

    @Test
    void robotLinksPackagesAreFreeOfCycles() {
        JavaClasses link = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.link");
        slices().matching("org.kheperasim.(**)")
                .should().beFreeOfCycles()
                .because("a package that uses its user cannot be understood, tested or moved without it;"
                        + " break the cycle by moving the shared type down or inverting an interface")
                .check(link);
    }
}
