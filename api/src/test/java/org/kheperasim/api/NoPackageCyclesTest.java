package org.kheperasim.api;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * No two packages of the api module depend on each other both ways, each package its own slice. The
 * layers, bottom up: {@code api.spi} (the port a backend implements; it speaks in its own types),
 * {@code api} (the student API, which delegates to the port), {@code api.binding} (what makes and
 * drives a student's controller, using both).
 */
class NoPackageCyclesTest {
    private static JavaClasses api;

    @BeforeAll
    static void importClasses() {
        api = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.api");
    }

    @Test
    void theApisPackagesAreFreeOfCycles() {
        slices().matching("org.kheperasim.(**)").should().beFreeOfCycles()
                .because("a package that uses its user cannot be understood, tested or moved without it;"
                        + " break the cycle by moving the shared type down or inverting an interface")
                .check(api);
    }

    @Test
    void thePortUsesNothingOfTheStudentApi() {
        noClasses().that().resideInAPackage("org.kheperasim.api.spi")
                .should().dependOnClassesThat().resideInAnyPackage("org.kheperasim.api", "org.kheperasim.api.binding")
                .because("the port lies below the student API: a backend implements it without the API's types")
                .check(api);
    }

    @Test
    void theStudentApiDoesNotReachTheBinding() {
        noClasses().that().resideInAPackage("org.kheperasim.api")
                .should().dependOnClassesThat().resideInAPackage("org.kheperasim.api.binding")
                .check(api);
    }
}
