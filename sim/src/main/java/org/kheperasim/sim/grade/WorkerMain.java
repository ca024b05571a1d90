package org.kheperasim.sim.grade;

import java.nio.file.Path;
import org.kheperasim.sim.grade.worker.WorkerLoop;

/**
 * The entry point of a warm worker JVM ({@code java -cp SIMULATOR WorkerMain --classpath DIR --scratch DIR},
 * started by the grader, in the sandbox): it makes one submission's graded runs one after another, each
 * exactly as {@link GradedRun} makes it in a JVM of its own, taking the requests from standard input
 * (docs/grading.md, "Warm workers"; the protocol is {@code grade.worker.WorkerProtocol}'s).
 */
public final class WorkerMain {
    /** The main class of a warm worker's JVM. */
    public static final String MAIN = WorkerMain.class.getName();

    private WorkerMain() {
    }

    /**
     * Serve the grader until its standard input ends.
     *
     * @param args {@code --classpath DIR --scratch DIR}
     */
    public static void main(String[] args) {
        String classpath = null;
        String scratch = null;
        for (int i = 0; i + 1 < args.length; i += 2) {
            switch (args[i]) {
                case "--classpath" -> classpath = args[i + 1];
                case "--scratch" -> scratch = args[i + 1];
                default -> classpath = null;
            }
        }
        if (classpath == null || scratch == null || args.length != 4) {
            System.err.println("khepera-sim: error: a worker needs --classpath DIR --scratch DIR (the grader starts"
                    + " workers; see docs/grading.md)");
            System.err.flush();
            Runtime.getRuntime().halt(2);
            return;
        }
        WorkerLoop.serve(GradedRun::run, Path.of(scratch), classpath, GradedRun::warmUp);
    }
}
