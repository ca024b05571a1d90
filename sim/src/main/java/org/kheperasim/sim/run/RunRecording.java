package org.kheperasim.sim.run;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.files.TextFiles;

/**
 * A run recording: the folder that replays a run exactly, with the start arena, the stamped edits,
 * the settings, a copy of the controller's compiled classes when they are not bundled ({@code
 * classes/}), and the command line that replays them ({@code replay.txt}), which {@code verify}
 * reads back. Paths in it are relative to the folder, so a recording can be handed on whole.
 */
public final class RunRecording {
    /** The most bytes of compiled classes copied into a recording; a larger classpath is named, not copied. */
    static final long MAX_CLASS_BYTES = 16L << 20;
    /** The folder in a recording that holds the controller's classes. */
    public static final String CLASSES = "classes";
    private static final String REPLAY = "replay.txt";
    /** The largest replay.txt read, bytes: it holds one command line and a few comments. */
    private static final long MAX_REPLAY_TXT_BYTES = 1L << 20;

    private RunRecording() {
    }

    /**
     * Save what replays a run exactly.
     *
     * @param session the run
     * @param reachedSeconds how far the run went, simulated seconds (for the replay hint)
     * @param classpath where its controller came from (empty for a bundled one)
     * @param settings the run's settings
     * @param dir the folder to write to
     * @throws UncheckedIOException naming the folder when it cannot be written
     */
    public static void save(RunSession session, double reachedSeconds, List<Path> classpath,
            Settings settings, Path dir) {
        try {
            Files.createDirectories(dir);
            ArenaFormat.save(session.arena(), dir.resolve("start.arena"));
            session.edits().save(dir.resolve("run.edits"));
            SettingsFile.save(settings, dir.resolve("run.settings"));
            StringBuilder cmd = new StringBuilder("java -jar khepera-sim.jar run --arena start.arena --controller ")
                    .append(session.controllerClass()).append(" --seed ").append(session.seed())
                    .append(" --edits run.edits");
            if (!classpath.isEmpty()) {
                cmd.append(" --classpath ")
                        .append(quoted(String.join(File.pathSeparator, copyClasses(classpath, dir))));
            }
            settings.overrides().forEach((k, v) -> cmd.append(" --set ").append(k).append('=').append(v));
            AtomicFiles.write(dir.resolve(REPLAY),
                    "# Replays the run exactly, from this folder; add --seconds T for how long"
                    + " (the window ran to " + String.format(Locale.ROOT, "%.3f", reachedSeconds)
                    + " s) and --trace FILE for the trace:\n" + cmd + "\n");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording in " + dir + ": " + e.getMessage(), e);
        }
    }

    /**
     * Copies the classpath into the recording's {@code classes/} (a lone folder as {@code classes},
     * several entries as {@code classes/1}, {@code classes/2}, a jar as {@code classes/NAME.jar}), so
     * the recording replays where the classes are not, such as an instructor's machine; when they are
     * too large to copy, their absolute paths instead.
     *
     * @return the classpath as replay.txt names it: relative to the recording, or absolute when not copied
     */
    private static List<String> copyClasses(List<Path> classpath, Path dir) throws IOException {
        long bytes = 0;
        for (Path p : classpath) {
            bytes += size(p);
        }
        List<String> named = new ArrayList<>();
        if (bytes > MAX_CLASS_BYTES) {
            for (Path p : classpath) {
                named.add(p.toAbsolutePath().toString());
            }
            return named;
        }
        Path classes = dir.resolve(CLASSES);
        for (int i = 0; i < classpath.size(); i++) {
            Path from = classpath.get(i);
            boolean alone = classpath.size() == 1 && Files.isDirectory(from);
            Path to = alone ? classes : Files.isDirectory(from) ? classes.resolve(Integer.toString(i + 1))
                    : classes.resolve((i + 1) + "-" + from.getFileName());
            copy(from, to);
            named.add(dir.relativize(to).toString());
        }
        return named;
    }

    private static long size(Path p) throws IOException {
        if (!Files.isDirectory(p)) {
            return Files.size(p);
        }
        try (Stream<Path> files = Files.walk(p)) {
            long sum = 0;
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                sum += Files.size(f);
            }
            return sum;
        }
    }

    private static void copy(Path from, Path to) throws IOException {
        if (!Files.isDirectory(from)) {
            Files.createDirectories(to.getParent());
            AtomicFiles.write(to, Files.readAllBytes(from));
            return;
        }
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                Path target = to.resolve(from.relativize(f).toString());
                Files.createDirectories(target.getParent());
                AtomicFiles.write(target, Files.readAllBytes(f));
            }
        }
    }

    /**
     * The classpath a recording replays with, as its replay.txt names it.
     *
     * @param dir a run recording folder
     * @return its classpath, resolved against the folder; empty when it names none (a bundled controller)
     *     or has no replay.txt
     */
    public static List<Path> classpath(Path dir) {
        Path replay = dir.resolve(REPLAY);
        if (!Files.isRegularFile(replay)) {
            return List.of();
        }
        List<String> words = words(TextFiles.readUtf8(replay, MAX_REPLAY_TXT_BYTES, "replay.txt",
                (line, what) -> new InputFileException(replay.toString(), line, what)).lines()
                .filter(l -> !l.startsWith("#") && !l.isBlank()).findFirst().orElse(""));
        int at = words.indexOf("--classpath");
        if (at < 0 || at + 1 >= words.size()) {
            return List.of();
        }
        List<Path> out = new ArrayList<>();
        for (String entry : words.get(at + 1).split(File.pathSeparator)) {
            if (!entry.isEmpty()) {
                out.add(dir.resolve(entry));
            }
        }
        return out;
    }

    /** @return the word, in single quotes when a shell would split it */
    private static String quoted(String word) {
        return word.matches("[A-Za-z0-9_./:=@%+,-]+") ? word : "'" + word.replace("'", "'\\''") + "'";
    }

    /** Splits a command line as a shell does with plain words and single quotes (what {@link #quoted} writes). */
    private static List<String> words(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder w = new StringBuilder();
        boolean inQuote = false;
        boolean any = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (c == '\'') {
                inQuote = !inQuote;
                any = true;
            } else if (c == '\\' && !inQuote && i + 1 < line.length()) {
                w.append(line.charAt(++i));
                any = true;
            } else if (Character.isWhitespace(c) && !inQuote) {
                if (any) {
                    out.add(w.toString());
                    w.setLength(0);
                    any = false;
                }
            } else {
                w.append(c);
                any = true;
            }
        }
        if (any) {
            out.add(w.toString());
        }
        return out;
    }
}
