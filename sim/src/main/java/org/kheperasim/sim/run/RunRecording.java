package org.kheperasim.sim.run;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * A run recording: the folder that replays a run exactly, with the start arena, the stamped edits,
 * the settings and the command line that replays them ({@code replay.txt}).
 */
public final class RunRecording {
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
    public static void save(RunSession session, double reachedSeconds, List<Path> classpath, Settings settings, Path dir) {
        try {
            Files.createDirectories(dir);
            ArenaFormat.save(session.arena(), dir.resolve("start.arena"));
            session.edits().save(dir.resolve("run.edits"));
            SettingsFile.save(settings, dir.resolve("run.settings"));
            StringBuilder cmd = new StringBuilder("java -jar khepera-sim.jar run --arena start.arena --controller ")
                    .append(session.controllerClass()).append(" --seed ").append(session.seed()).append(" --edits run.edits");
            if (!classpath.isEmpty()) {
                cmd.append(" --classpath ");
                cmd.append(String.join(File.pathSeparator, classpath.stream().map(p -> p.toAbsolutePath().toString()).toList()));
            }
            settings.overrides().forEach((k, v) -> cmd.append(" --set ").append(k).append('=').append(v));
            AtomicFiles.write(dir.resolve("replay.txt"), "# Replays the run exactly; add --seconds T for how long (the window ran to "
                    + String.format(Locale.ROOT, "%.3f", reachedSeconds) + " s) and --trace FILE for the trace:\n" + cmd + "\n");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording in " + dir + ": " + e.getMessage(), e);
        }
    }
}
