package org.kheperasim.sim.web;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.ReplayFiles;

/**
 * A run as one self-contained web page that replays it in any browser, from a USB stick or a
 * course site: no server, no network, nothing to install. The arena as the window draws it, the
 * robots moving with their trails, play and pause at x0.25 to x64, a timeline to scrub with marks
 * at contacts, cap moves and failures, the sensor panel and the score at every moment.
 *
 * <p>A 600 s run at 50 ms stays under {@link #BUDGET_BYTES}: the samples are packed
 * ({@link TapeEncoder}), and when a run has more than fits (several robots, a long run) the sensor
 * values, then the poses, are kept at every n-th sample; the page says so. Every page is written
 * atomically, and the same run gives the same bytes.
 */
public final class RunPage {
    /** The most a page may take, bytes: under 200 KB however a kilobyte is counted. */
    public static final long BUDGET_BYTES = 199_000;

    /**
     * What was written.
     *
     * @param file           the page
     * @param bytes          its size, bytes
     * @param seconds        the simulated time it replays, s
     * @param robots         robots shown
     * @param poseEveryMs    the period of the poses kept, ms
     * @param sensorsEveryMs the period of the sensor values kept, ms
     */
    public record Written(Path file, long bytes, double seconds, int robots, long poseEveryMs, long sensorsEveryMs) {
    }

    private RunPage() {
    }

    /**
     * The page of a trace ({@code run --trace}), a window's run recording folder or a robot-link
     * recording, with the arena found as the window's File > Open recording finds it.
     *
     * @param traceOrRecording the file or folder
     * @param out              the page to write
     * @return what was written
     * @throws org.kheperasim.sim.files.InputFileException naming the file and line at fault
     * @throws UncheckedIOException naming the file that cannot be read or written
     */
    public static Written write(Path traceOrRecording, Path out) {
        return write(ReplayFiles.open(traceOrRecording), RunOutcome.none(), out);
    }

    /**
     * The page of a trace whose arena the caller has (grade's traces lie apart from their arenas).
     *
     * @param trace   the trace
     * @param arena   the arena it was recorded in
     * @param outcome what the run's result says (failures, final facts), or {@link RunOutcome#none()}
     * @param out     the page to write
     * @return what was written
     */
    public static Written write(Path trace, Arena arena, RunOutcome outcome, Path out) {
        return write(ReplayFiles.open(trace, arena), outcome, out);
    }

    /**
     * @param replay  a run read back ({@link ReplayFiles#open})
     * @param outcome what the run's result says, or {@link RunOutcome#none()}
     * @param out     the page to write
     * @return what was written
     */
    public static Written write(Replay replay, RunOutcome outcome, Path out) {
        return write(replay, outcome, replay.source(), out);
    }

    /**
     * The page of a run read back from working files whose paths mean nothing to the page's reader
     * (grade's replay of a run, the window's run so far): the page says {@code source} where it would
     * name them, so the same run gives the same page wherever its files lay.
     *
     * @param replay  a run read back ({@link ReplayFiles#open})
     * @param outcome what the run's result says, or {@link RunOutcome#none()}
     * @param source  what the page was made from, in words, e.g. {@code the grader's replay of the run}
     * @param out     the page to write
     * @return what was written
     */
    public static Written write(Replay replay, RunOutcome outcome, String source, Path out) {
        RunTape tape = RunTape.of(replay);
        String title = outcome.title().isEmpty() ? title(replay) : outcome.title();
        List<String> notes = replay.notes().stream().map(n -> n.replace(replay.source(), source)).toList();
        PageModel.About about = new PageModel.About(title, source, notes, failures(tape, outcome, List.of()));
        return save(out, tape, about, outcome);
    }

    /**
     * The page of a run recorded as it went (a run without a trace: {@code run --html}, the window).
     *
     * @param recorder the recorder attached to the run
     * @param outcome  what the run's result says ({@link RunOutcome#of}), or {@link RunOutcome#none()}
     * @param out      the page to write
     * @return what was written
     */
    public static Written write(RunPageRecorder recorder, RunOutcome outcome, Path out) {
        return write(recorder, outcome, "", out);
    }

    /**
     * As {@link #write(RunPageRecorder, RunOutcome, Path)}, saying what the run was (grade: the
     * grader's replay of a run's command log).
     *
     * @param recorder the recorder attached to the run
     * @param outcome  what the run's result says, or {@link RunOutcome#none()}
     * @param source   what the page was made from, in words, or empty
     * @param out      the page to write
     * @return what was written
     */
    public static Written write(RunPageRecorder recorder, RunOutcome outcome, String source, Path out) {
        RunTape tape = recorder.tape();
        synchronized (recorder) {
            if (tape.robots().isEmpty()) {
                throw new IllegalStateException(
                        "the run recorded no sample: attach the recorder to the run before it starts");
            }
            String title = outcome.title().isEmpty() ? tape.arenas().get(0).arena().name() : outcome.title();
            PageModel.About about =
                    new PageModel.About(title, source, List.of(), failures(tape, outcome, recorder.errors()));
            return save(out, tape, about, outcome);
        }
    }

    /** A page and how its samples were packed. */
    record Page(String html, TapeEncoder.Encoded packed) {
    }

    static Page page(RunTape tape, PageModel.About about, RunOutcome outcome) {
        List<ScoreTimeline.Moment> scores = ScoreTimeline.of(tape, outcome.finalFacts());
        boolean coverageAtEnd = outcome.finalFacts() != null;
        TapeEncoder.Encoded whole = TapeEncoder.pack(tape, 1, 1);
        // What the page takes besides its samples; the thinned samples' description differs by a few digits.
        String wholeJson = PageModel.json(about, tape, whole, scores, coverageAtEnd);
        long fixed = Template.BYTES + wholeJson.getBytes(StandardCharsets.UTF_8).length
                + 2L * about.title().getBytes(StandardCharsets.UTF_8).length + 200;
        TapeEncoder.Encoded packed = TapeEncoder.encode(tape, StrictMath.max(20_000, BUDGET_BYTES - fixed), whole);
        String json = packed == whole ? wholeJson : PageModel.json(about, tape, packed, scores, coverageAtEnd);
        // The run first: a title cannot then be mistaken for the placeholder of the run.
        String html = Template.TEXT.replace("/*RUN*/",
                "var RUN = " + json + ";\nvar SAMPLES = \"" + packed.base64() + "\";")
                .replace("<!--TITLE-->", escape(about.title()));
        return new Page(html, packed);
    }

    private static Written save(Path out, RunTape tape, PageModel.About about, RunOutcome outcome) {
        if (Files.isDirectory(out)) {
            throw new IllegalArgumentException("cannot write the page " + out
                    + ": it is a folder; give a file name such as "
                    + out.resolve("run.html"));
        }
        Path parent = out.toAbsolutePath().getParent();
        if (parent != null && !Files.isDirectory(parent)) {
            throw new IllegalArgumentException("cannot write the page " + out + ": its folder " + parent
                    + " does not exist; create it or give another path");
        }
        Page page = page(tape, about, outcome);
        byte[] bytes = page.html().getBytes(StandardCharsets.UTF_8);
        try {
            AtomicFiles.write(out, bytes);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the page " + out + ": " + e.getMessage(), e);
        }
        long sample = PageModel.sampleMs(tape);
        long pose = sample * page.packed().poseStride();
        return new Written(out, bytes.length, tape.endMs() / 1000.0, tape.robots().size(), pose,
                pose * page.packed().sensorStride());
    }

    /**
     * The failures to mark: the outcome's, dated by when the run was seen to fail or by the
     * controller's error line; and any the recorder saw that the outcome does not name.
     */
    static List<RunOutcome.Failure> failures(RunTape tape, RunOutcome outcome, List<ConsoleLine> errors) {
        List<RunOutcome.Failure> out = new ArrayList<>();
        java.util.Set<Integer> named = new java.util.HashSet<>();
        for (RunOutcome.Failure f : outcome.failures()) {
            ConsoleLine line = firstError(tape, errors, f.robot());
            // The console's error line is the most precise: its time is the failure's, its text names the student's
            // line.
            double t = f.seconds();
            if (Double.isNaN(t) && line != null) {
                t = line.timeNanos() / 1e9;
            }
            if (Double.isNaN(t) && f.robot() < tape.robots().size() && tape.robots().get(f.robot()).failedMs >= 0) {
                t = tape.robots().get(f.robot()).failedMs / 1000.0;
            }
            String message = line != null && (f.message().isEmpty() || line.text().contains(f.message()))
                    ? line.text() : f.message();
            out.add(new RunOutcome.Failure(f.robot(), t, f.status(), message));
            named.add(f.robot());
        }
        for (int i = 0; i < tape.robots().size(); i++) {
            RunTape.Track r = tape.robots().get(i);
            if (r.failedMs >= 0 && !named.contains(i)) {
                ConsoleLine line = firstError(tape, errors, i);
                out.add(new RunOutcome.Failure(i,
                        line == null ? r.failedMs / 1000.0 : line.timeNanos() / 1e9, r.failedStatus,
                        line == null ? "" : line.text()));
            }
        }
        return out;
    }

    private static ConsoleLine firstError(RunTape tape, List<ConsoleLine> errors, int robot) {
        for (ConsoleLine l : errors) {
            boolean lone = tape.robots().size() == 1;
            if (lone || robot < tape.robots().size() && l.source().equals(tape.robots().get(robot).name)) {
                return l;
            }
        }
        return null;
    }

    /** A title from the trace's header: {@code WallFollower in maze · seed 1}. */
    private static String title(Replay replay) {
        if (replay.kind() == Replay.Kind.LINK_RECORDING) {
            return "A real robot's run (robot-link recording)";
        }
        Path src = Path.of(replay.source());
        Map<String, String> h = header(replay.kind() == Replay.Kind.RECORDING ? src.resolve("run.trace") : src);
        String controller = h.getOrDefault("controller", "");
        controller = controller.substring(controller.lastIndexOf('.') + 1);
        String arena = h.getOrDefault("arena", replay.arena().name()).split(" ")[0];
        return (controller.isEmpty() ? "A run" : controller) + " in " + arena
                + (h.containsKey("seed") ? " · seed " + h.get("seed") : "");
    }

    private static Map<String, String> header(Path trace) {
        Map<String, String> h = new LinkedHashMap<>();
        try (BufferedReader in = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
            for (int i = 0; i < 40; i++) {
                String line = in.readLine();
                if (line == null || !line.startsWith("# ")) {
                    break;
                }
                String[] f = line.substring(2).split(" ", 2);
                h.putIfAbsent(f[0], f.length > 1 ? f[1] : "");
            }
        } catch (IOException | UncheckedIOException e) {
            // the title only: the samples were read already
        }
        return h;
    }

    /** The page's HTML, CSS and script, read once from the jar. */
    private static final class Template {
        static final String TEXT = read("page.html").replace("/*SCRIPT*/", compact(read("page.js")));
        static final long BYTES = TEXT.getBytes(StandardCharsets.UTF_8).length;

        /** The script without its indentation and whole-line comments: a fifth smaller, the same program. */
        private static String compact(String js) {
            StringBuilder out = new StringBuilder(js.length());
            for (String line : js.split("\n")) {
                String t = line.strip();
                if (!t.isEmpty() && !t.startsWith("//")) {
                    out.append(t).append('\n');
                }
            }
            return out.toString();
        }

        private static String read(String name) {
            try (InputStream in = RunPage.class.getResourceAsStream(name)) {
                if (in == null) {
                    throw new IllegalStateException("the jar lacks org/kheperasim/sim/web/" + name + "; rebuild it");
                }
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
