package org.kheperasim.testing;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

/**
 * No two packages of the testing module depend on each other both ways. It is one package today
 * ({@code org.kheperasim.testing}); the rule keeps any package split out of it (a facade over the
 * engine's events, say) below or above it, never both. Each package is its own slice.
 */
class NoPackageCyclesTest {

    @Test
    void theTestingModulesPackagesAreFreeOfCycles() {
        JavaClasses testing = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.testing");
        slices().matching("org.kheperasim.(**)")
                .should().beFreeOfCycles()
                .because("a package that uses its user cannot be understood, tested or moved without it;"
                        + " break the cycle by moving the shared type down or inverting an interface")
                .check(testing);
    }
}
