package org.kheperasim.sim;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noFields;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.IrSensor;

/**
 * One package knows a robot's numbers: {@code org.kheperasim.sim.engine.robot} (the robot types and
 * their files). Every other class of the simulator reads them from a
 * {@code RobotType}: none places sensors by the student API's {@link IrSensor} poses, none makes a
 * robot type's parts, none keeps a constant of its own for a body radius, a wheel base, a speed
 * unit or a motor period.
 */
class RobotNumbersTest {
    private static final String ROBOT = "org.kheperasim.sim.engine.robot..";
    private static JavaClasses classes;

    @BeforeAll
    static void importClasses() {
        classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.sim");
    }

    @Test
    void noOtherPackagePlacesSensorsByTheKheperasPoses() {
        noClasses().that().resideOutsideOfPackage(ROBOT)
                .should().callMethod(IrSensor.class, "xMm").orShould().callMethod(IrSensor.class, "yMm")
                .orShould().callMethod(IrSensor.class, "headingDeg").orShould().callMethod(IrSensor.class, "values")
                .because("a robot's sensors are its RobotType's (docs/robot-files.md), not the Khepera's")
                .check(classes);
    }

    @Test
    void onlyTheRobotPackageMakesARobotsParts() {
        // The window's robot editor (gui.robot) makes robot types from what a person draws and types: each
        // edit is written as a robot file and read back by the robot package's reader before it is taken.
        noClasses().that().resideOutsideOfPackage(ROBOT).and().resideOutsideOfPackage("org.kheperasim.sim.gui.robot..")
                .should().callConstructorWhere(com.tngtech.archunit.core.domain.JavaConstructorCall.Predicates.target(
                        com.tngtech.archunit.core.domain.properties.HasOwner.Predicates.With.owner(
                                com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage(ROBOT))))
                .because("a robot's numbers come from a robot file, read in org.kheperasim.sim.engine.robot")
                .check(classes);
    }

    @Test
    void noOtherPackageKeepsARobotConstant() {
        noFields().that().areDeclaredInClassesThat().resideOutsideOfPackage(ROBOT).and().areStatic().and().areFinal()
                .should().haveNameMatching(".*(BODY_RADIUS|ROBOT_RADIUS|WHEEL_BASE|SPEED_UNIT|MOTOR_PERIOD|MM_PER_PULSE).*")
                .because("the robot's numbers live in its RobotType")
                .check(classes);
    }
}
