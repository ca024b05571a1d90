package org.kheperasim.sim.run;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The import a controller's source left out: the paper's Appendix {@code Robot.java} names
 * {@code CurrentRobotState} and {@code MessagePasser} without importing them (the original's controllers
 * compiled beside the simulator's classes, in the default package). Finds the API's classes among the
 * compiler's "cannot find symbol" errors, and names the one line that imports them.
 */
final class MissingImports {
    /** The import of the student API. */
    static final String API_IMPORT = "import org.kheperasim.api.*;";
    /** The import of the WSU simulator's API. */
    static final String WSU_IMPORT = "import edu.wsu.KheperaSimulator.*;";

    private static final Pattern SYMBOL = Pattern.compile("symbol:\\s+class\\s+(\\w+)");

    private MissingImports() {
    }

    /** @return the API classes (simple names) that the errors say cannot be found, in order */
    static Set<String> apiClasses(List<ControllerCompiler.Problem> problems) {
        return classesIn(problems, "org.kheperasim.api.");
    }

    private static Set<String> classesIn(List<ControllerCompiler.Problem> problems, String pkg) {
        Set<String> found = new LinkedHashSet<>();
        for (ControllerCompiler.Problem p : problems) {
            String name = missingClass(p);
            if (name != null && exists(pkg + name)) {
                found.add(name);
            }
        }
        return found;
    }

    /** @return the problems, each error that names a class of an API not imported ending with the line to add */
    static List<ControllerCompiler.Problem> annotate(List<ControllerCompiler.Problem> problems) {
        List<ControllerCompiler.Problem> out = new ArrayList<>();
        for (ControllerCompiler.Problem p : problems) {
            String name = missingClass(p);
            String line = name == null ? null
                    : exists("org.kheperasim.api." + name) ? API_IMPORT
                    : exists("edu.wsu.KheperaSimulator." + name) ? WSU_IMPORT : null;
            out.add(line == null ? p : new ControllerCompiler.Problem(p.error(), p.line(), p.column(),
                    p.message() + "\n  " + name + " is a class of the simulator's API: add the line `" + line
                    + "` at the top of the file", p.source()));
        }
        return out;
    }

    /**
     * @param text a source in the default package
     * @return the same source with the API imported on its first line (so every line keeps its number)
     */
    static String withApiImport(String text) {
        return API_IMPORT + " " + text;
    }

    private static String missingClass(ControllerCompiler.Problem p) {
        if (!p.error() || !p.message().startsWith("cannot find symbol")) {
            return null;
        }
        Matcher m = SYMBOL.matcher(p.message());
        return m.find() ? m.group(1) : null;
    }

    private static boolean exists(String className) {
        try {
            Class.forName(className, false, MissingImports.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }
}
