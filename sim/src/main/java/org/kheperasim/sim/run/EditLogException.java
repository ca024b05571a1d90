package org.kheperasim.sim.run;

import org.kheperasim.sim.files.InputFileException;

/** An edit log ({@code run.edits}) that cannot be read or replayed: {@code file:line: what is wrong and the fix}. */
public final class EditLogException extends InputFileException {

    private static final long serialVersionUID = 1L;

    /**
     * @param source the file's name as the user knows it
     * @param line   1-based line at fault (0: the log as a whole)
     * @param what   what is wrong and the fix
     */
    public EditLogException(String source, int line, String what) {
        super(source, line, what);
    }
}
