package org.kheperasim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.cli.Main;

/**
 * The figures the docs quote are what a user sees today: the README's sample result line for seed 1
 * (every number but the wall time), the size of that run's web page as docs/web-replay.md and
 * docs/grading.md give it, and the build command robot-link's page gives. Each is read from the page
 * itself and checked against a real run of the command the page shows.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class DocsFiguresTest {
    /** The wall time in a result line: the one part that differs from machine to machine. */
    private static final Pattern WALL = Pattern.compile("simulated in [0-9.]+ s \\([0-9]+x real time\\)");

    @TempDir
    Path dir;

    private static String page(String name) throws IOException {
        return Files.readString(ReadmeSnippets.root().resolve(name));
    }

    private static String find(String text, String regex, String what) {
        Matcher m = Pattern.compile(regex, Pattern.DOTALL).matcher(text);
        assertTrue(m.find(), what + " is no longer where this test looks (" + regex + ")");
        return m.group(1);
    }

    /** Runs the command line in this JVM: standard output, with the exit status checked. */
    private static String run(List<String> args) {
        PrintStream old = System.out;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            code = Main.commandLine().execute(args.toArray(String[]::new));
        } finally {
            System.setOut(old);
        }
        String out = o.toString(StandardCharsets.UTF_8);
        assertEquals(0, code, args + ": " + out);
        return out;
    }

    @Test
    void theReadmesSeedOneRunPrintsItsSampleLineAndItsPageIsTheSizeTheDocsSay() throws IOException {
        String readme = page("README.md");
        String command = find(readme, "The same run headless, with a\\s+one-line result:\\s+```sh\\n([^\\n]+)\\n```",
                "README's headless run command");
        assertTrue(command.startsWith("java -jar sim/target/khepera-sim.jar run "), command);
        String sample = find(readme, "\\n`(WallFollower in maze: [^`]+)`", "README's sample result line");
        assertFalse(sample.contains("..."), "the whole line, as it is printed: " + sample);

        List<String> args = new ArrayList<>(List.of(command.substring("java -jar sim/target/khepera-sim.jar ".length()).split(" +")));
        Path html = dir.resolve("run.html");
        args.addAll(List.of("--html", html.toString()));
        String[] lines = run(args).strip().split("\\R");
        assertEquals("seed 1", lines[0], "the seed first, as the README says");
        assertTrue(lines[1].startsWith("mode tethered: "), "then where the controller runs: " + lines[1]);
        String result = lines[2];
        assertEquals(WALL.matcher(sample).replaceAll("simulated in T"), WALL.matcher(result).replaceAll("simulated in T"),
                "README.md's sample line is what seed 1 prints today (but the wall time)");

        // The page of that run (the same run with --html): web-replay.md quotes what run prints and gives its size.
        double kb = Files.size(html) / 1024.0;
        String wrote = lines[3];
        String replay = page("docs/web-replay.md");
        String quoted = find(replay, "`(wrote run\\.html: [^`]+)`", "web-replay.md's 'wrote run.html' line");
        String sizeNow = String.format(Locale.ROOT, "wrote %s: %.1f KB,", html, kb);
        assertTrue(wrote.startsWith(sizeNow), "run says what it wrote: " + wrote);
        assertEquals(kb, Double.parseDouble(find(quoted, "run\\.html: ([0-9.]+) KB", "its size")), 0.05,
                "web-replay.md's example of what run prints: " + quoted);
        double table = Double.parseDouble(find(replay, "\\| `maze`, `WallFollower`, 1 robot \\| ([0-9.]+) KB", "the size table"));
        assertEquals(kb, table, 0.5, "web-replay.md's table: the maze run's page");
        // grading.md: a graded run's page is made from the grader's replay of the same run, sampled as run --html samples.
        double about = Double.parseDouble(find(page("docs/grading.md"), "about ([0-9.]+) KB for a 600 s run of one robot",
                "grading.md's page size"));
        assertEquals(kb, about, about * 0.10, "grading.md's 'about' figure, within 10 %");
    }

    @Test
    void robotLinksPageBuildsAsTheReadmeDoes() throws IOException {
        String build = find(page("README.md"), "```sh\\n[^`]*?\\n(mvn [^&\\n]+) && java -jar sim/target/khepera-sim.jar\\n",
                "README's build command");
        String robotLink = page("docs/robot-link.md");
        assertTrue(robotLink.contains("Build it with `" + build + "`"), "robot-link.md builds with the README's " + build);
        assertFalse(robotLink.contains("`mvn -o package`"), "mvn -o package runs every test and needs a filled cache");
    }
}
