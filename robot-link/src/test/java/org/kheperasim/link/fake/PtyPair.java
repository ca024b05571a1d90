package org.kheperasim.link.fake;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * A pseudo-terminal pair made by socat, with links in a folder the test owns: the host end for
 * robot-link (opened through jSerialComm), the robot end for the fake robot (opened as a plain file).
 */
public final class PtyPair implements AutoCloseable {
    private final Process socat;
    private final Path host;
    private final Path robot;

    private PtyPair(Process socat, Path host, Path robot) {
        this.socat = socat;
        this.host = host;
        this.robot = robot;
    }

    /**
     * Skip the test when socat is missing, except in CI ({@code CI=true}) where that is a failure.
     */
    public static void assumeSocat() {
        boolean found = false;
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin:/bin").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, "socat"))) {
                found = true;
                break;
            }
        }
        if (!found) {
            if ("true".equals(System.getenv("CI"))) {
                fail("socat is not installed, and CI=true requires the pty tests to run: apt-get install -y socat");
            }
            Assumptions.assumeTrue(false, "socat is not installed (apt-get install -y socat); pty test skipped");
        }
    }

    /**
     * @param dir a folder of the test's own (a JUnit @TempDir)
     * @return a running pair whose links exist
     * @throws IOException when socat does not start
     */
    public static PtyPair open(Path dir) throws IOException, InterruptedException {
        assumeSocat();
        Path a = dir.resolve("host");
        Path b = dir.resolve("robot");
        Process p = new ProcessBuilder("socat", "-d", "-d", "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b)
                .redirectErrorStream(true).redirectOutput(dir.resolve("socat.log").toFile()).start();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!(Files.exists(a) && Files.exists(b))) {
            if (!p.isAlive() || System.nanoTime() > end) {
                p.destroyForcibly();
                fail("socat did not make the pty pair in 10 s: " + Files.readString(dir.resolve("socat.log")));
            }
            Thread.sleep(10);
        }
        // socat logs "starting data transfer loop" once both ends are ready.
        while (!Files.readString(dir.resolve("socat.log")).contains("starting data transfer loop")
                && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        return new PtyPair(p, a, b);
    }

    /** @return the host end's path (a symlink to /dev/pts/N) */
    public Path host() {
        return host;
    }

    /** @return the robot end's path */
    public Path robot() {
        return robot;
    }

    /** End socat: both ptys hang up, as when a USB adapter is pulled. */
    public void kill() throws InterruptedException {
        socat.destroy();
        if (!socat.waitFor(5, TimeUnit.SECONDS)) {
            socat.destroyForcibly();
        }
    }

    @Override
    public void close() throws InterruptedException {
        kill();
    }
}
