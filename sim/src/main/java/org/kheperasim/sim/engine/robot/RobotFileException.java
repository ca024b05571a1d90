package org.kheperasim.sim.engine.robot;

import org.kheperasim.sim.files.InputFileException;

/**
 * A robot file that cannot be read. The message is {@code source:line: what is wrong and the fix},
 * ready to show a person as it is.
 */
public final class RobotFileException extends InputFileException {

    private static final long serialVersionUID = 1L;

    /**
     * @param source the file's name as the user knows it
     * @param line   1-based line number of the offending line (0: the file as a whole)
     * @param what   what is wrong and how to fix it
     */
    public RobotFileException(String source, int line, String what) {
        super(source, line, what);
    }
}
