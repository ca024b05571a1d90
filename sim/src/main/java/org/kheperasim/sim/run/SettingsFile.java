package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.TextFiles;

/**
 * Settings as a text file a person can read: {@code key=value} lines (only what differs from the
 * defaults), {@code #} comments. Saved next to an arena as {@code NAME.settings} (the arena format
 * has no settings), or as a named profile under {@code ~/.khepera-sim/profiles/}.
 */
public final class SettingsFile {
    /** File name extension, with the dot. */
    public static final String EXTENSION = ".settings";
    /** Largest settings file, bytes. */
    public static final long MAX_FILE_BYTES = 1L << 20;

    private SettingsFile() {
    }

    /** @return the profile folder, {@code ~/.khepera-sim/profiles} */
    public static Path profiles() {
        return Path.of(System.getProperty("user.home"), ".khepera-sim", "profiles");
    }

    /**
     * @param arenaFile an arena file
     * @return the settings file saved with it: {@code maze.arena} → {@code maze.settings}
     */
    public static Path besideArena(Path arenaFile) {
        String name = arenaFile.getFileName().toString().replaceFirst("\\.arena$", "");
        return arenaFile.resolveSibling(name + EXTENSION);
    }

    /** @param settings settings @return the file's text */
    public static String write(Settings settings) {
        StringBuilder sb = new StringBuilder(
                "# khepera-sim settings: only what differs from the defaults; list every key with"
                        + " 'khepera-sim settings'\n");
        for (Map.Entry<String, String> e : settings.overrides().entrySet()) {
            sb.append(e.getKey()).append('=').append(e.getValue()).append('\n');
        }
        return sb.toString();
    }

    /**
     * @param text a settings file's text
     * @param source how errors name it
     * @return the settings
     * @throws SettingsFileException naming {@code source:line}, what is wrong and the fix
     */
    public static Settings parse(String text, String source) {
        Settings s = Settings.defaults();
        String[] lines = (text.startsWith("\uFEFF") ? text.substring(1) : text).split("\\R");
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                s = s.with(line);
            } catch (IllegalArgumentException e) {
                throw new SettingsFileException(source, i + 1, e.getMessage());
            }
        }
        return s;
    }

    /**
     * @param file a settings file
     * @return the settings
     * @throws SettingsFileException naming the file and line at fault
     * @throws UncheckedIOException when the file cannot be read
     */
    public static Settings load(Path file) {
        String source = file.toString();
        return parse(TextFiles.readUtf8(file, MAX_FILE_BYTES, "settings file",
                (line, what) -> new SettingsFileException(source, line, what)), source);
    }

    /** @param settings what to save @param file where, atomically ({@link AtomicFiles}) */
    public static void save(Settings settings, Path file) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            AtomicFiles.write(file, write(settings));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save settings " + file + ": " + e.getMessage(), e);
        }
    }
}
