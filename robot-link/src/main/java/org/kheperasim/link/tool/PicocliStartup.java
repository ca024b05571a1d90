package org.kheperasim.link.tool;

/**
 * Start-up of both command lines. Picocli registers type converters for {@code java.sql} and
 * {@code java.time} types by reflection whenever a command line is built, loading about 80 classes
 * at every start; no option of either tool has such a type. Picocli's own switch, the system
 * property {@value #EXCLUDES}, leaves them out (unless the user has set it).
 */
public final class PicocliStartup {
    /** Picocli's system property: regular expressions of the built-in converters' types to leave out. */
    public static final String EXCLUDES = "picocli.converters.excludes";

    private PicocliStartup() {
    }

    /** Leave out the converters no option uses. Call before the first {@code new CommandLine(...)}. */
    public static void skipUnusedConverters() {
        if (System.getProperty(EXCLUDES) == null) {
            System.setProperty(EXCLUDES, "java\\.sql\\..*,java\\.time\\..*");
        }
    }
}
