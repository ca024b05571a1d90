package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Map;
import org.kheperasim.sim.engine.Settings;

/**
 * Settings as a text file a person can read: {@code key=value} lines (only what differs from the
 * defaults), {@code #} comments. Saved next to an arena as {@code NAME.settings} (the arena format
 * has no settings), or as a named profile under {@code ~/.khepera-sim/profiles/}.
 */
public final class SettingsFile {
    /** File name extension, with the dot. */
    public static final String EXTENSION = ".settings";

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
        StringBuilder sb = new StringBuilder("# khepera-sim settings: only what differs from the defaults; list every key with 'khepera-sim settings'\n");
        for (Map.Entry<String, String> e : settings.overrides().entrySet()) {
            sb.append(e.getKey()).append('=').append(e.getValue()).append('\n');
        }
        return sb.toString();
    }

    /**
     * @param text a settings file's text
     * @param source how errors name it
     * @return the settings
     * @throws IllegalArgumentException naming {@code source:line} and what is wrong
     */
    public static Settings parse(String text, String source) {
        Settings s = Settings.defaults();
        String[] lines = text.split("\\R");
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                s = s.with(line);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage(), e);
            }
        }
        return s;
    }

    /** @param file a settings file @return the settings */
    public static Settings load(Path file) {
        try {
            return parse(Files.readString(file, StandardCharsets.UTF_8), file.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read settings " + file + ": " + e.getMessage(), e);
        }
    }

    /** @param settings what to save @param file where, atomically */
    public static void save(Settings settings, Path file) {
        try {
            Path parent = file.toAbsolutePath().getParent();
            Files.createDirectories(parent);
            Path temp = Files.createTempFile(parent, file.getFileName().toString(), ".part");
            Files.writeString(temp, write(settings), StandardCharsets.UTF_8);
            try {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (java.nio.file.AtomicMoveNotSupportedException e) {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save settings " + file + ": " + e.getMessage(), e);
        }
    }
}
