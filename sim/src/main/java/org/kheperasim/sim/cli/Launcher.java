package org.kheperasim.sim.cli;

/**
 * The runnable jar's entry point ({@code java -jar khepera-sim.jar ...}): starts the command warm
 * when it can ({@link WarmStart}), else runs it here ({@link Main}). A class of its own, so that the
 * JVM that only starts another loads nothing of the command line (picocli's classes, which
 * {@link Main} needs to be linked).
 */
public final class Launcher {
    private Launcher() {
    }

    /**
     * @param args the command line's arguments
     */
    public static void main(String[] args) {
        int code = WarmStart.relaunch(args);
        if (code >= 0) {
            System.exit(code);
        }
        Main.main(args);
    }
}
