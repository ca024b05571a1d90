package org.kheperasim.sim.arena;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.wsu.WsuWorld;
import org.kheperasim.sim.arena.wsu.WsuWorldException;

/**
 * The one place where a file becomes an arena, whatever its format, recognised by its content: a
 * WSU Khepera Simulator world file (a Java serialization stream, starting with {@code 0xACED}) or
 * an arena text file ({@code docs/arena-format.md}).
 */
public final class ArenaFiles {
    private ArenaFiles() {
    }

    /**
     * Reads an arena file of either format; warnings about a WSU world (objects clipped, left out,
     * the robot moved) go to standard error as {@code file: warning: ...}.
     *
     * @param file the file
     * @return the arena
     * @throws ArenaFormatException if a text file is not a valid arena ({@code file:line: what})
     * @throws WsuWorldException    if a WSU world file is damaged ({@code file: byte N: what})
     * @throws UncheckedIOException if the file cannot be read
     */
    public static Arena load(Path file) {
        return load(file, warning -> System.err.println(file + ": warning: " + warning));
    }

    /**
     * Reads an arena file of either format.
     *
     * @param file     the file
     * @param warnings where a WSU world's warnings go, one sentence each
     * @return the arena
     * @throws ArenaFormatException if a text file is not a valid arena
     * @throws WsuWorldException    if a WSU world file is damaged
     * @throws UncheckedIOException if the file cannot be read
     */
    public static Arena load(Path file, Consumer<String> warnings) {
        return isWsuWorld(file) ? WsuWorld.read(file, warnings) : ArenaFormat.load(file);
    }

    /**
     * @param file a file
     * @return whether it starts like a WSU world file (the serialization stream's {@code 0xACED});
     *     false when it cannot be read (loading it then says why)
     */
    public static boolean isWsuWorld(Path file) {
        if (!Files.isRegularFile(file)) {
            return false;   // not opened: a pipe would hang; reading it as an arena file refuses it
        }
        try (InputStream in = Files.newInputStream(file)) {
            return WsuWorld.isWsuWorld(in.readNBytes(2));
        } catch (IOException e) {
            return false;
        }
    }
}
