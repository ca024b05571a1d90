package org.kheperasim.sim.run;

import org.kheperasim.sim.files.InputFileException;

/** A settings file that cannot be read: {@code file:line: what is wrong and the fix}. */
public final class SettingsFileException extends InputFileException {

    private static final long serialVersionUID = 1L;

    /**
     * @param source the file's name as the user knows it
     * @param line   1-based line at fault (0: the file as a whole)
     * @param what   what is wrong and the fix
     */
    public SettingsFileException(String source, int line, String what) {
        super(source, line, what);
    }
}
