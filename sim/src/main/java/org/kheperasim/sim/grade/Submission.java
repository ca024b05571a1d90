package org.kheperasim.sim.grade;

import java.nio.file.Path;

/**
 * One student's submission, compiled (or found compiled) and ready to run.
 *
 * @param student    the folder's name
 * @param classpath  the folder with the compiled classes (null when it failed to compile)
 * @param controller the controller class's name (null when there is none)
 * @param problem    why it cannot run (the compiler's first error, or no controller class); null when it can
 * @param empty      true when nothing was handed in: the folder holds no {@code .java} or {@code .class} file
 */
public record Submission(String student, Path classpath, String controller, String problem, boolean empty) {
    /** A submission with something in it. */
    public Submission(String student, Path classpath, String controller, String problem) {
        this(student, classpath, controller, problem, false);
    }

    /** @return true when it compiled and holds a controller */
    public boolean runnable() {
        return problem == null;
    }
}
