package org.kheperasim.sim;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noFields;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaCall;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The layers, checked in the compiled classes: the model knows nothing of the screen (MASON's
 * rule), renderers draw into a Graphics2D without Swing, the engine sits below the controller host,
 * controllers see only the student API, and every file is saved atomically but by the few writers
 * that must write as they go.
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
        // The robot types (engine.robot) are data below the arena, which names each robot's type; the
        // rest of the engine is above it.
        noClasses().that().resideInAPackage("..sim.arena..")
                .should().dependOnClassesThat(JavaClass.Predicates.resideInAnyPackage("..sim.engine..", "..sim.host..",
                        "..sim.run..", "..sim.gui..", "..sim.cli..", "..sim.serve..", "..sim.edit..", "..sim.task..",
                        "..sim.grade..").and(DescribedPredicate.not(JavaClass.Predicates.resideInAPackage("..sim.engine.robot.."))))
                .check(sim);
    }

    @Test
    void theRobotTypesStandBelowTheEngine() {
        noClasses().that().resideInAPackage("..sim.engine.robot..")
                .should().dependOnClassesThat(JavaClass.Predicates.resideInAPackage("..sim..")
                        .and(DescribedPredicate.not(JavaClass.Predicates.resideInAnyPackage("..sim.engine.robot..", "..sim.files.."))))
                .because("a robot type is data: it is read from a file and knows nothing of the engine that runs it")
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
                .and().doNotHaveFullyQualifiedName("org.kheperasim.sim.commandlog.OpenLoopReplay")
                .and().resideOutsideOfPackage("..sim.engine..")
                .should().callMethod("org.kheperasim.sim.engine.Engine", "advance")
                .because("one class decides when the world moves and who runs next (a controller's clock asks it);"
                        + " an engine without controllers (the protocol server's) runs by Engine.runUntil, and a"
                        + " graded run's replay (OpenLoopReplay) runs no controller either: it plays the command log"
                        + " at the ticks the log names, each robot's turn as Engine.advance hands it out")
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

    /** Classes that must write as they go, with why: no other class writes a file but through files.AtomicFiles. */
    private static final Map<String, String> STREAMING_WRITERS = Map.of(
            "org.kheperasim.sim.trace.LineFileWriter", "a run's trace is written as the run goes, in whole lines at least"
                    + " once a second, so that a killed run leaves a trace that reads up to its last second",
            "org.kheperasim.sim.grade.Journal", "the grading's journal appends each finished run and forces it to disk as"
                    + " it ends, so that a killed grading loses nothing",
            "org.kheperasim.sim.commandlog.LogChannel", "a graded run's command log is received as it streams in over its"
                    + " socket (up to 256 MiB), into a working file of the grader's",
            "org.kheperasim.sim.grade.Verdict", "the grader's replay writes the run's trace as it computes it, into a working"
                    + " file of its own (megabytes; deleted once its picture and page are made)",
            "org.kheperasim.sim.host.CpuAffinity", "a controller thread claims a core with a lock file, in which nothing is"
                    + " written",
            "org.kheperasim.sim.sandbox.Reexec", "a sandboxed run's trace goes to a file bind-mounted into the box, which"
                    + " must exist (empty) under its own name before the box starts",
            "org.kheperasim.sim.cli.EvaluateCommand", "evaluate --out writes each job's outcome line as the job ends and"
                    + " flushes it, so that a killed evaluation keeps every outcome it finished (a learning loop may read"
                    + " the file as it grows)");

    /** A call that writes a file in place: Files.write*, copy, move, an output stream or channel on a file. */
    private static final DescribedPredicate<JavaCall<?>> WRITES_A_FILE = new DescribedPredicate<>(
            "write a file in place (Files.write*/newOutputStream/newBufferedWriter/copy/move, FileChannel.open,"
                    + " ImageIO.write to a File, new FileOutputStream/FileWriter/RandomAccessFile, a PrintStream or"
                    + " PrintWriter on a file name)") {
        @Override
        public boolean test(JavaCall<?> call) {
            String owner = call.getTarget().getOwner().getName();
            String name = call.getTarget().getName();
            List<String> params = call.getTarget().getRawParameterTypes().stream().map(JavaClass::getName).toList();
            boolean onAFile = !params.isEmpty() && (params.get(0).equals("java.io.File") || params.get(0).equals("java.lang.String"));
            return switch (owner) {
                case "java.nio.file.Files" -> name.startsWith("write") || name.equals("newOutputStream")
                        || name.equals("newBufferedWriter") || name.equals("copy") || name.equals("move");
                case "java.nio.channels.FileChannel", "java.nio.channels.AsynchronousFileChannel" -> name.equals("open");
                case "javax.imageio.ImageIO" -> name.equals("write") && params.contains("java.io.File");
                case "java.io.FileOutputStream", "java.io.FileWriter", "java.io.RandomAccessFile" -> name.equals("<init>");
                case "java.io.PrintStream", "java.io.PrintWriter" -> name.equals("<init>") && onAFile;
                default -> false;
            };
        }
    };

    @Test
    void everyFileIsSavedAtomicallyButTheStreamsThatMustWriteAsTheyGo() {
        StringBuilder why = new StringBuilder("a reader never sees half a file and a failed save leaves the old one, so"
                + " every file goes through files.AtomicFiles (a temporary file, then one rename); except the streaming"
                + " writers:");
        STREAMING_WRITERS.entrySet().stream().sorted(Map.Entry.comparingByKey())
                .forEach(e -> why.append(' ').append(e.getKey()).append(" (").append(e.getValue()).append(");"));
        noClasses().that().resideOutsideOfPackage("..sim.files..")
                .and(new DescribedPredicate<JavaClass>("are not a streaming writer") {
                    @Override
                    public boolean test(JavaClass c) {
                        String top = c.getName().contains("$") ? c.getName().substring(0, c.getName().indexOf('$')) : c.getName();
                        return !STREAMING_WRITERS.containsKey(top);
                    }
                })
                .should().callCodeUnitWhere(WRITES_A_FILE)
                .because(why.substring(0, why.length() - 1))
                .check(sim);
    }

    @Test
    void theStreamingWritersStillExist() {
        for (String c : STREAMING_WRITERS.keySet()) {
            org.junit.jupiter.api.Assertions.assertTrue(sim.contain(c), c + " is named an exception to the atomic save, but is"
                    + " gone: take it off the list");
        }
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
