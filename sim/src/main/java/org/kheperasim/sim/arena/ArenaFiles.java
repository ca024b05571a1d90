package org.kheperasim.sim.arena;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ServiceLoader;
import java.util.function.Consumer;

/**
 * The one place where a file becomes an arena, whatever its format, recognised by its content: a
 * WSU Khepera Simulator world file (a Java serialization stream, starting with {@code 0xACED}) or
 * an arena text file ({@code docs/arena-format.md}). WSU world files are read by the importer of
 * {@code org.kheperasim.sim.arena.wsu}, found as the {@link WsuWorldReader} service.
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
     * @throws IllegalArgumentException if a WSU world file is damaged ({@code file: byte N: what};
     *     {@code org.kheperasim.sim.arena.wsu.WsuWorldException})
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
     * @throws IllegalArgumentException if a WSU world file is damaged ({@code WsuWorldException})
     * @throws UncheckedIOException if the file cannot be read
     */
    public static Arena load(Path file, Consumer<String> warnings) {
        return isWsuWorld(file) ? readWsuWorld(file, warnings) : ArenaFormat.load(file);
    }

    /**
     * @param file     a WSU world file
     * @param warnings where the import's warnings go
     * @return the world as an arena, read by the simulator's {@link WsuWorldReader}
     */
    static Arena readWsuWorld(Path file, Consumer<String> warnings) {
        return Reader.INSTANCE.read(file, warnings);
    }

    /** The WSU world reader, looked up once, in the class loader of the arena package. */
    private static final class Reader {
        static final WsuWorldReader INSTANCE = ServiceLoader.load(WsuWorldReader.class,
                        WsuWorldReader.class.getClassLoader()).findFirst()
                .orElseThrow(() -> new IllegalStateException("no WSU world reader on the class path (the"
                        + " simulator's jar names one in META-INF/services/" + WsuWorldReader.class.getName() + ")"));

        private Reader() {
        }
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
            return WsuWorldReader.isWsuWorld(in.readNBytes(2));
        } catch (IOException e) {
            return false;
        }
    }
}
