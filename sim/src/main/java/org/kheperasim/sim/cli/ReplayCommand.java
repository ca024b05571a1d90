package org.kheperasim.sim.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.files.BoundedLines;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.trace.TraceFormatException;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code replay --html}: a recorded run as a web page that replays it in any browser. */
@Command(name = "replay", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Turn a recorded run into one self-contained web page that replays it in any browser: the arena,"
                + " the robots with their trails, play/pause and speeds, a timeline with marks at"
                + " contacts, cap moves and failures, the sensor panel and the score at every moment. No server, no"
                + " network: open the file, put it on a USB stick or upload it to a course site.",
            "RECORDING is a trace file (run --trace), a run recording folder (the window's File > Save run recording)"
                    + " or a robot-link recording of a real robot. To watch it in the window instead: File >"
                    + " Open recording."})
final class ReplayCommand implements Callable<Integer> {
    @Option(names = "--html", required = true, paramLabel = "OUT.html",
            description = "write the page here (replaced if it exists)")
    Path html;

    @Option(names = "--arena", paramLabel = "FILE",
            description = "the arena a trace was recorded in (default: start.arena or the arena file of the same name"
                    + " beside the trace, or the bundled arena it names)")
    Path arenaFile;

    @Parameters(index = "0", paramLabel = "RECORDING|TRACE",
            description = "a trace file, a run recording folder or a robot-link recording")
    Path recording;

    @Override
    public Integer call() {
        if (!Files.exists(recording)) {
            throw new IllegalArgumentException("no trace or recording " + recording + "; give a trace written by"
                    + " 'run --trace FILE', a run recording folder or a robot-link recording");
        }
        if (!Files.isDirectory(recording)) {   // before anything opens it: a pipe would hang, a device run on
            TextFiles.checkFile(recording, ReplayFiles.MAX_FILE_BYTES, "replay",
                    (line, what) -> new TraceFormatException(recording.toString(), line, what));
        }
        if (arenaFile != null && Files.isDirectory(recording)) {
            throw new IllegalArgumentException("--arena " + arenaFile + ": the run recording " + recording
                    + " carries its own start.arena; give --arena only with a trace file");
        }
        long start = System.nanoTime();
        Replay replay = arenaFile == null ? ReplayFiles.open(recording) : ReplayFiles.open(recording, arena());
        replay.notes().forEach(n -> System.err.println("note: " + n));
        RunPage.Written w = RunPage.write(replay, RunOutcome.none(), html);
        System.out.println(String.format(Locale.ROOT,
                "wrote %s: %.1f KB, %.1f s of %d robot%s, poses every %d ms, sensor values"
                + " every %d ms, in %.2f s", w.file(), w.bytes() / 1024.0, w.seconds(), w.robots(),
                w.robots() == 1 ? "" : "s",
                w.poseEveryMs(), w.sensorsEveryMs(), (System.nanoTime() - start) / 1e9));
        return ExitCodes.OK;
    }

    /**
     * The arena given with --arena: it must be the one the trace names by its SHA-256, or the walls drawn would
     * mislead.
     */
    private Arena arena() {
        Arena a = ArenaFiles.load(arenaFile, note -> { });
        try (BufferedReader in = Files.newBufferedReader(recording, StandardCharsets.UTF_8)) {
            BoundedLines lines = new BoundedLines(in, 1 << 16,
                    (l, what) -> new TraceFormatException(recording.toString(), l, what + " (not a trace's header)"));
            for (String line = lines.next(); line != null && line.startsWith("#"); line = lines.next()) {
                String[] f = line.split(" ");
                if (f.length >= 4 && f[1].equals("arena") && f[3].startsWith("sha256=")
                        && !f[3].substring(7).equals(ArenaFormat.sha256(a))) {
                    throw new IllegalArgumentException("--arena " + arenaFile + " is not the arena " + recording
                            + " was recorded in (its sha256 is " + ArenaFormat.sha256(a) + ", the trace names "
                            + f[3].substring(7)
                            + "); give the arena file the run used");
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + recording + ": " + e.getMessage(), e);
        }
        return a;
    }
}
