package org.kheperasim.sim.arena;

import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * How the arena files read a world file of the WSU Khepera Simulator ({@link ArenaFiles}, and the
 * arena format's {@code wsu-world PATH} line): the reader is the importer of
 * {@code org.kheperasim.sim.arena.wsu}, which builds an {@link Arena} and so sits above this package.
 * {@link ArenaFiles} finds it as a service ({@code META-INF/services}), so that the arena knows nothing
 * of the importer's package and the two do not depend on each other both ways.
 */
public interface WsuWorldReader {
    /** The two bytes every WSU world file starts with: a Java serialization stream's magic number. */
    int MAGIC = 0xACED;

    /**
     * @param head the first bytes of a file (two are looked at)
     * @return whether they are a WSU world file's
     */
    static boolean isWsuWorld(byte[] head) {
        return head.length >= 2 && (head[0] & 0xFF) == (MAGIC >>> 8) && (head[1] & 0xFF) == (MAGIC & 0xFF);
    }

    /**
     * Reads a WSU world file as an arena.
     *
     * @param file     the world file
     * @param warnings where the import's warnings go (objects clipped, left out, the robot moved), one sentence each
     * @return the arena, valid as an arena file
     * @throws IllegalArgumentException if the file is damaged ({@code file: byte N: what}; the importer's own type)
     * @throws java.io.UncheckedIOException if the file cannot be read
     */
    Arena read(Path file, Consumer<String> warnings);
}
