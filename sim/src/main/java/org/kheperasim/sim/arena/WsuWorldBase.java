package org.kheperasim.sim.arena;

import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import org.kheperasim.sim.files.InputFileException;

/**
 * The arena format's {@code wsu-world PATH} line: a world file of the WSU Khepera Simulator, read as
 * the base the arena file builds on (its size, walls, lamps, caps and start pose), so an instructor
 * keeps the course's world files and adds regions and tasks beside them.
 */
final class WsuWorldBase {
    private WsuWorldBase() {
    }

    /**
     * @param path   the path as written, relative to the arena file's folder (or absolute)
     * @param folder the arena file's folder, or null when the text did not come from a file
     * @param source how errors name the arena file
     * @param line   the line of the {@code wsu-world} keyword
     * @return the world as an arena
     * @throws ArenaFormatException naming the line and the fix when the world cannot be used
     */
    static Arena read(String path, Path folder, String source, int line) {
        if (folder == null) {
            throw new ArenaFormatException(source, line, "wsu-world works only in an arena file (its path is taken"
                    + " relative to the file's folder); save the arena as a file next to the world and open that");
        }
        Path file;
        try {
            file = folder.resolve(path).normalize();
        } catch (InvalidPathException e) {
            throw new ArenaFormatException(source, line, "wsu-world '" + TokenNumbers.shorten(path)
                    + "' is not a usable path (" + e.getReason() + "); give the WSU world file's path");
        }
        if (!Files.isRegularFile(file)) {
            throw new ArenaFormatException(source, line, "wsu-world: there is no file '" + TokenNumbers.shorten(path)
                    + "' (looked for " + file
                    + "); give the WSU world file's path, relative to this arena file's folder");
        }
        if (!ArenaFiles.isWsuWorld(file)) {
            throw new ArenaFormatException(source, line, "wsu-world: " + file + " is not a WSU world file (it does not"
                    + " start with the serialization stream's bytes AC ED); name a world file saved by the"
                    + " WSU simulator");
        }
        try {
            return ArenaFiles.readWsuWorld(file, warning -> System.err.println(file + ": warning: " + warning));
        } catch (InputFileException e) {
            throw e;   // the file itself refused (its size, its kind), as the reader says it
        } catch (IllegalArgumentException | UncheckedIOException e) {   // a damaged world (WsuWorldException)
            throw new ArenaFormatException(source, line, "wsu-world: " + e.getMessage());
        }
    }
}
