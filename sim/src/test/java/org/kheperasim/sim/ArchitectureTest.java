package org.kheperasim.sim;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noFields;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The layers, checked in the compiled classes: the model knows nothing of the screen (MASON's
 * rule), renderers draw into a Graphics2D without Swing, the engine sits below the controller host,
 * and controllers see only the student API.
 */
class ArchitectureTest {
    private static JavaClasses sim;
    private static JavaClasses controllers;

    @BeforeAll
    static void importClasses() {
        ClassFileImporter importer = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS);
        sim = importer.importPackages("org.kheperasim.sim");
        controllers = importer.importPackages("org.kheperasim.controllers");
    }

    @Test
    void onlyTheWindowTouchesTheScreen() {
        noClasses().that().resideInAnyPackage("..sim.engine..", "..sim.host..", "..sim.run..", "..sim.trace..",
                        "..sim.arena..", "..sim.edit..", "..sim.serve..", "..sim.replay..", "..sim.task..")
                .should().dependOnClassesThat().resideInAnyPackage("java.awt..", "javax.swing..")
                .because("the engine and everything it runs on work headless; only the gui package draws")
                .check(sim);
    }

    @Test
    void renderersDrawWithoutSwing() {
        noClasses().that().haveSimpleNameEndingWith("Renderer")
                .should().dependOnClassesThat().resideInAPackage("javax.swing..")
                .because("a renderer draws a snapshot into any Graphics2D, so it is testable into an image")
                .check(sim);
    }

    @Test
    void theEngineKnowsNothingAboveIt() {
        noClasses().that().resideInAPackage("..sim.engine..")
                .should().dependOnClassesThat().resideInAnyPackage("..sim.host..", "..sim.run..", "..sim.gui..",
                        "..sim.cli..", "..sim.serve..", "..sim.edit..", "..sim.trace..")
                .check(sim);
    }

    @Test
    void theHostKnowsNothingAboveIt() {
        noClasses().that().resideInAPackage("..sim.host..")
                .should().dependOnClassesThat().resideInAnyPackage("..sim.run..", "..sim.gui..", "..sim.cli..",
                        "..sim.serve..", "..sim.edit..")
                .check(sim);
    }

    @Test
    void theArenaModelStandsAlone() {
        noClasses().that().resideInAPackage("..sim.arena..")
                .should().dependOnClassesThat().resideInAnyPackage("..sim.engine..", "..sim.host..", "..sim.run..",
                        "..sim.gui..", "..sim.cli..", "..sim.serve..", "..sim.edit..", "..sim.task..", "..sim.grade..")
                .check(sim);
    }

    @Test
    void scoringAndGradingStayBelowTheWindowAndTheCommandLine() {
        noClasses().that().resideInAnyPackage("..sim.task..", "..sim.grade..")
                .should().dependOnClassesThat().resideInAnyPackage("..sim.gui..", "..sim.cli..", "..sim.serve..")
                .because("the window and the command line call the scoring and grading, never the other way round")
                .check(sim);
    }

    @Test
    void onlyTheLockstepStepsTheWorld() {
        noClasses().that().doNotHaveFullyQualifiedName("org.kheperasim.sim.host.Lockstep")
                .and().resideOutsideOfPackage("..sim.engine..")
                .should().callMethod("org.kheperasim.sim.engine.Engine", "advance")
                .because("one class decides when the world moves and who runs next (a controller's clock asks it);"
                        + " an engine without controllers (the protocol server's) runs by Engine.runUntil")
                .check(sim);
    }

    @Test
    void aControllersLifeIsKeptInOnePlace() {
        noFields().that().areDeclaredInClassesThat().haveFullyQualifiedName("org.kheperasim.sim.host.ControllerHost")
                .or().areDeclaredInClassesThat().haveFullyQualifiedName("org.kheperasim.sim.host.StepHost")
                .should().haveRawType(boolean.class)
                .orShould().haveRawType(org.kheperasim.sim.host.ControllerStatus.class)
                .because("a controller's life (started, stopping, ended, and why) is one state machine, ControllerLife,"
                        + " not flags written from several threads")
                .check(sim);
    }

    @Test
    void controllersSeeOnlyTheStudentApi() {
        classes().that().resideInAPackage("org.kheperasim.controllers..")
                .should().onlyDependOnClassesThat().resideInAnyPackage("org.kheperasim.controllers..",
                        "org.kheperasim.api", "java..")
                .because("a controller must run unchanged on the real robot, which has only the api")
                .check(controllers);
    }
}
