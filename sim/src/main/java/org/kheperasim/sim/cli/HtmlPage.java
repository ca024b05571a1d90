package org.kheperasim.sim.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPage;
import org.kheperasim.sim.web.RunPageRecorder;

/**
 * {@code run --html FILE}: the run as one web page that replays it in any browser (docs/web-replay.md),
 * recorded as the run goes, with its failures (the student's line where a controller threw) and its
 * own score. The page's path is checked before the run, so a long run is not made for nothing.
 */
final class HtmlPage {
    private final Path file;
    private final RunPageRecorder recorder;
    private final long start = System.nanoTime();

    private HtmlPage(Path file, RunPageRecorder recorder) {
        this.file = file;
        this.recorder = recorder;
    }

    /**
     * @param file  the page to write
     * @param arena the arena as the run starts
     * @param edits the run's arena edits, or null
     * @param run   the run, which the recorder is attached to
     * @return the page to write once the run has ended
     * @throws IllegalArgumentException if the page cannot be written there, with the fix
     */
    static HtmlPage attach(Path file, Arena arena, EditLog edits, Simulation.Builder run) {
        check(file);
        HtmlPage page = new HtmlPage(file, new RunPageRecorder(arena, edits));
        run.listener(page.recorder, RunPageRecorder.PERIOD_MILLIS);
        return page;
    }

    /** @return the recorder, which the run's console lines go to as well */
    RunPageRecorder recorder() {
        return recorder;
    }

    /**
     * @param result the run's result
     * @param info   where to say what was written
     */
    void write(RunResult result, PrintStream info) {
        RunPage.Written w = RunPage.write(recorder, RunOutcome.of(result), file);
        info.println(wrote(w, (System.nanoTime() - start) / 1e9));
    }

    /**
     * @param file the page to write
     * @throws IllegalArgumentException when it is a folder or its folder does not exist
     */
    static void check(Path file) {
        if (Files.isDirectory(file)) {
            throw new IllegalArgumentException("--html " + file + " is a folder; give a file name such as "
                    + file.resolve("run.html"));
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null && !Files.isDirectory(parent)) {
            throw new IllegalArgumentException("--html " + file + ": its folder " + parent
                    + " does not exist; create it or"
                    + " give another path");
        }
    }

    /** @return e.g. {@code wrote run.html: 167.9 KB, 600.0 s of 1 robot, poses every 50 ms, ...} */
    static String wrote(RunPage.Written w, double seconds) {
        return String.format(Locale.ROOT,
                "wrote %s: %.1f KB, %.1f s of %d robot%s, poses every %d ms, sensor values every %d ms,"
                + " in %.2f s", w.file(), w.bytes() / 1024.0, w.seconds(), w.robots(), w.robots() == 1 ? "" : "s",
                w.poseEveryMs(), w.sensorsEveryMs(), seconds);
    }

    /**
     * In the sandbox only the files given are writable, and a page is saved atomically beside its
     * name: so the boxed run writes a trace, and the page is made from it outside the box. Such a
     * page shows no failures and no floor coverage (a trace holds neither; docs/web-replay.md).
     */
    static final class Boxed {
        private final Path html;
        private final Path trace;
        private final boolean temporary;

        /**
         * @param html  the page to write
         * @param trace the trace the run writes anyway (--trace), or null
         * @param args  the boxed run's arguments: {@code --html} is taken out, {@code --trace} added when missing
         * @param write the files the box may write: the trace is added
         */
        Boxed(Path html, Path trace, List<String> args, List<Path> write) {
            check(html);
            this.html = html;
            this.temporary = trace == null;
            try {
                this.trace = trace != null ? trace : Files.createTempFile("khepera-run-page-", ".trace");
            } catch (IOException e) {
                throw new UncheckedIOException("cannot make a temporary trace for the page: " + e.getMessage(), e);
            }
            List<String> kept = new ArrayList<>();
            for (int i = 0; i < args.size(); i++) {
                if (args.get(i).equals("--html")) {
                    i++;
                } else if (!args.get(i).startsWith("--html=")) {
                    kept.add(args.get(i));
                }
            }
            if (temporary) {
                kept.addAll(List.of("--trace", this.trace.toString()));
                write.add(this.trace);
            }
            args.clear();
            args.addAll(kept);
        }

        /**
         * @param arena the run's arena
         * @param info  where to say what was written
         */
        void write(Arena arena, PrintStream info) {
            long start = System.nanoTime();
            try {
                if (Files.size(trace) > 0) {
                    RunPage.Written w = RunPage.write(trace, arena, RunOutcome.none(), html);
                    info.println(wrote(w, (System.nanoTime() - start) / 1e9)
                            + " (from the sandboxed run's trace: no failures"
                            + " or floor coverage shown)");
                }
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read the sandboxed run's trace " + trace + ": "
                        + e.getMessage(), e);
            } finally {
                if (temporary) {
                    try {
                        Files.deleteIfExists(trace);
                    } catch (IOException e) {
                        // a temporary file left behind
                    }
                }
            }
        }
    }
}
