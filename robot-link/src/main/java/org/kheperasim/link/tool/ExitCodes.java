package org.kheperasim.link.tool;

/** The exit status of both tools; scripts learn from it alone whether a run succeeded. */
public final class ExitCodes {
    /** Everything went as asked. */
    public static final int OK = 0;
    /** The controller or the run failed: it threw, hung, lost its link, or the tool hit a bug. */
    public static final int FAILED = 1;
    /** Bad input: an option, a file, a name, or a setup the tool cannot use (no display, no such port). */
    public static final int BAD_INPUT = 2;

    /** The table as it appears at the end of every {@code --help}. */
    public static final String HELP = "Exit status: 0 ok; 1 the controller or run failed; 2 bad input"
            + " (an option, file, name or connection the tool cannot use).";

    private ExitCodes() {
    }
}
