package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;

/**
 * A headless Chromium for the page tests: a fresh profile each time, no network, no first-run
 * chores. Skipped without Chromium on a laptop; under {@code CI=true} a missing Chromium fails.
 */
final class Chromium {
    private static final String[] NAMES = {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"};

    private final Path exe;
    private final Path scratch;

    private Chromium(Path exe, Path scratch) {
        this.exe = exe;
        this.scratch = scratch;
    }

    /** @return Chromium on the PATH, or null */
    static Path find() {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            for (String name : NAMES) {
                Path p = Path.of(dir, name);
                if (Files.isExecutable(p)) {
                    return p;
                }
            }
        }
        return null;
    }

    /**
     * @param what the test, for the skip message
     * @param scratch a folder for the browser's throw-away profiles
     * @return a browser, or the test is skipped (failed under CI) when there is none
     */
    static Chromium require(String what, Path scratch) {
        Path exe = find();
        if (exe == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Chromium is not installed, and CI=true requires " + what + " to run: apt-get install -y chromium");
            }
            Assumptions.assumeTrue(false, "Chromium is not installed (apt-get install -y chromium): the web page tests need it");
        }
        return new Chromium(exe, scratch);
    }

    /** Loads {@code page#fragment} in a {@code w} × {@code h} window and saves what it shows. */
    void screenshot(Path page, String fragment, int w, int h, Path png) throws IOException, InterruptedException {
        Files.deleteIfExists(png);
        run(page, fragment, w, h, 0, "--screenshot=" + png.toAbsolutePath());
        assertTrue(Files.isRegularFile(png), "Chromium wrote no screenshot " + png);
    }

    /**
     * Loads {@code page#fragment}, lets {@code virtualMillis} of the page's time pass (timers and
     * animation frames run; the machine's speed does not matter), and returns the document then.
     */
    String dom(Path page, String fragment, int w, int h, int virtualMillis) throws IOException, InterruptedException {
        return run(page, fragment, w, h, virtualMillis, "--dump-dom");
    }

    /** @return the value of the body's {@code data-NAME} attribute in a dumped document, or null */
    static String bodyData(String dom, String name) {
        Matcher m = Pattern.compile("<body[^>]*\\sdata-" + name + "=\"([^\"]*)\"").matcher(dom);
        return m.find() ? m.group(1) : null;
    }

    private String run(Path page, String fragment, int w, int h, int virtualMillis, String action)
            throws IOException, InterruptedException {
        Path profile = Files.createTempDirectory(Files.createDirectories(scratch), "chromium");
        List<String> cmd = new ArrayList<>(List.of(exe.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--user-data-dir=" + profile, "--force-device-scale-factor=1", "--hide-scrollbars",
                "--window-size=" + w + "," + h));
        if (virtualMillis > 0) {
            cmd.add("--virtual-time-budget=" + virtualMillis);
        }
        cmd.add(action);
        cmd.add(page.toUri() + (fragment.isEmpty() ? "" : "#" + fragment));
        Path out = profile.resolve("stdout.txt");
        Path err = profile.resolve("stderr.txt");
        Process p = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            fail("Chromium did not finish within 120 s: " + String.join(" ", cmd));
        }
        String text = Files.readString(out, StandardCharsets.UTF_8);
        assertTrue(p.exitValue() == 0, "Chromium exited with " + p.exitValue() + ": " + Files.readString(err, StandardCharsets.UTF_8));
        return text;
    }
}
