package org.kheperasim.sim.arena.wsu;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.ArenaFormatException;
import org.kheperasim.sim.arena.WsuWorldReader;
import org.kheperasim.sim.arena.wsu.StreamModel.Top;
import org.kheperasim.sim.arena.wsu.WsuWorldObjects.WsuObject;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.files.TextFiles;

/**
 * Reads a world (map) file of the original WSU Khepera Simulator into an {@link Arena}. Such a file
 * is a Java serialization stream holding a {@code java.util.Vector} of
 * {@code edu.wsu.KheperaSimulator.Vertex} objects; it is parsed by {@link SerialStreamParser}, which
 * instantiates nothing (deserialising a file with {@code ObjectInputStream} would run code named
 * by the file). The geometry is {@link WsuArenaBuilder}'s; the arena passes every check an
 * arena file must pass.
 */
public final class WsuWorld {
    /** The first two bytes of every Java serialization stream, hence of every WSU world file. */
    public static final int MAGIC = WsuWorldReader.MAGIC;
    /** The largest world file read, bytes (real ones are a few kilobytes). */
    public static final long MAX_BYTES = 16L << 20;

    private WsuWorld() {
    }

    /**
     * @param head the first bytes of a file (at least two to say yes)
     * @return whether they start a Java serialization stream, as every WSU world file does
     */
    public static boolean isWsuWorld(byte[] head) {
        return WsuWorldReader.isWsuWorld(head);
    }

    /**
     * What a world file held and the arena made from it.
     *
     * @param arena  the arena (border walls first, then the file's walls joined into runs, lights, caps)
     * @param walls  wall objects in the file
     * @param caps   cap objects in the file
     * @param balls  ball objects in the file (they become caps)
     * @param lights light objects in the file
     */
    public record Imported(Arena arena, int walls, int caps, int balls, int lights) {
    }

    /**
     * Reads a WSU world file.
     *
     * @param file     the file
     * @param warnings where to say what was clipped, left out or moved (one sentence each)
     * @return the arena, named after the file
     * @throws WsuWorldException   when the file is damaged or not a WSU world ({@code file: byte N: what})
     * @throws UncheckedIOException when the file cannot be read
     */
    public static Arena read(Path file, Consumer<String> warnings) {
        return importWorld(file, warnings).arena();
    }

    /**
     * Reads a WSU world file, with the counts of what it held.
     *
     * @param file     the file
     * @param warnings where to say what was clipped, left out or moved (one sentence each)
     * @return the arena, named after the file, and the counts
     * @throws WsuWorldException   when the file is damaged or not a WSU world ({@code file: byte N: what})
     * @throws UncheckedIOException when the file cannot be read
     */
    public static Imported importWorld(Path file, Consumer<String> warnings) {
        byte[] bytes;
        try {
            long size = TextFiles.regularSize(file, "WSU world file",
                    (line, what) -> new InputFileException(file.toString(), 0, what));
            if (size > MAX_BYTES) {
                throw new WsuWorldException(file.toString(), -1, "the file has " + size + " bytes, more than any WSU"
                        + " world (at most " + MAX_BYTES + " are read): it is not a world file");
            }
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read WSU world file " + file + ": " + e, e);
        }
        return importWorld(bytes, file.toString(), nameOf(file), warnings);
    }

    /**
     * Reads the bytes of a WSU world file.
     *
     * @param bytes    the whole file
     * @param source   how messages name the file
     * @param name     the arena's name (letters, digits, {@code _} and {@code -})
     * @param warnings where to say what was clipped, left out or moved
     * @return the arena
     * @throws WsuWorldException when the bytes are damaged or not a WSU world
     */
    public static Arena read(byte[] bytes, String source, String name, Consumer<String> warnings) {
        return importWorld(bytes, source, name, warnings).arena();
    }

    private static Imported importWorld(byte[] bytes, String source, String name, Consumer<String> warnings) {
        List<Top> contents = SerialStreamParser.parse(bytes, source);
        List<WsuObject> objects = WsuWorldObjects.read(contents, source, warnings);
        Arena arena = WsuArenaBuilder.build(name, objects, source, warnings);
        try {
            // The checks every arena file passes, so the arena can be saved and loaded again.
            arena = ArenaFormat.parse(ArenaFormat.write(arena), source);
        } catch (ArenaFormatException e) {
            throw new WsuWorldException(source, -1, "the arena made from this world is not valid ("
                    + e.getMessage() + "); please report this with the file");
        }
        int[] count = new int[5];
        for (WsuObject o : objects) {
            if (o.type() >= 1 && o.type() <= 4) {
                count[o.type()]++;
            }
        }
        return new Imported(arena, count[WsuObject.WALL], count[WsuObject.CAP], count[WsuObject.BALL],
                count[WsuObject.LIGHT]);
    }

    /**
     * @param file a world file
     * @return an arena name from its file name: the name without an extension, every character
     *     other than a letter, digit, {@code _} or {@code -} replaced by {@code _}
     */
    public static String nameOf(Path file) {
        Path fileName = file.getFileName();
        String base = fileName == null ? "" : fileName.toString();
        int dot = base.lastIndexOf('.');
        if (dot > 0) {
            base = base.substring(0, dot);
        }
        base = base.replaceAll("[^A-Za-z0-9_-]", "_");
        return base.isEmpty() ? "wsu-world" : base;
    }
}
