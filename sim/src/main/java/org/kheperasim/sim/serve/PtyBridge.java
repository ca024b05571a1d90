package org.kheperasim.sim.serve;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * A pseudo-terminal in front of the protocol server, for clients that only open serial ports (a C
 * program, a MATLAB toolbox, robot-link with a path): socat makes a pty with a link at a path the
 * user chose and, once a program opens it, connects it to the server's TCP port.
 *
 * <p>The command is {@code socat -d -d pty,raw,echo=0,wait-slave,link=PATH tcp:127.0.0.1:PORT}.
 * {@code wait-slave} holds the TCP connection back until a program opens the pty, so an idle pty
 * does not take the robot's one client slot. When that program closes the pty, socat ends (and the
 * robot stops, its client having gone); the bridge starts socat again so the path is there for the
 * next program.
 */
public final class PtyBridge implements AutoCloseable {
    private final Path link;
    private final List<String> command;
    private final Consumer<String> log;
    private final Thread supervisor;
    private volatile boolean closed;
    private volatile Process socat;

    private PtyBridge(Path link, List<String> command, Consumer<String> log) {
        this.link = link;
        this.command = command;
        this.log = log;
        this.supervisor = new Thread(this::supervise, "pty-bridge");
        this.supervisor.setDaemon(true);
    }

    /**
     * @param link where the pty's link goes
     * @param port the server's TCP port on this computer
     * @return the socat command line
     */
    public static List<String> command(Path link, int port) {
        return List.of("socat", "-d", "-d", "pty,raw,echo=0,wait-slave,link=" + link.toAbsolutePath(),
                "tcp:127.0.0.1:" + port);
    }

    /** @return true when socat is on the PATH */
    public static boolean socatInstalled() {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin:/bin").split(File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, "socat"))) {
                return true;
            }
        }
        return false;
    }

    /**
     * Start socat, and start it again each time it ends, until {@link #close()}.
     *
     * @param link where the pty's link goes (its folder must exist; an existing file there is an error)
     * @param port the server's TCP port on this computer
     * @param log told when the pty is ready and when socat restarts
     * @return the bridge, its link in place
     * @throws IOException when socat is missing, the link cannot be made, or socat does not start in 10 s
     */
    public static PtyBridge start(Path link, int port, Consumer<String> log) throws IOException, InterruptedException {
        if (!socatInstalled()) {
            throw new IOException("socat is not installed (apt-get install socat); without it, connect over TCP,"
                    + " or make the pty yourself: " + String.join(" ", command(link, port)));
        }
        if (Files.exists(link, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(link + " already exists; choose another --pty path or remove it");
        }
        PtyBridge b = new PtyBridge(link, command(link, port), log);
        b.launch();
        b.awaitLink();
        b.supervisor.start();
        return b;
    }

    private void launch() throws IOException {
        socat = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .start();
    }

    private void awaitLink() throws IOException, InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!Files.exists(link)) {
            if (!socat.isAlive() || System.nanoTime() > end) {
                socat.destroyForcibly();
                throw new IOException("socat did not make the pty at " + link + " (exit " +
                        (socat.isAlive() ? "none, still running" : socat.exitValue()) + "): " + String.join(" ", command));
            }
            Thread.sleep(10);
        }
    }

    private void supervise() {
        while (!closed) {
            try {
                socat.waitFor();
                if (closed) {
                    return;
                }
                log.accept("the program on " + link + " closed it; the pty is ready again");
                // socat removes its link on exit; give it a moment, then start a fresh one.
                Thread.sleep(50);
                launch();
                awaitLink();
            } catch (InterruptedException e) {
                return;
            } catch (IOException e) {
                log.accept("cannot restart socat for " + link + ": " + e.getMessage());
                return;
            }
        }
    }

    /** @return the pty's link */
    public Path link() {
        return link;
    }

    /** @return the socat command line in use */
    public List<String> commandLine() {
        return command;
    }

    /** Stop socat (a program on the pty sees a hang-up) and stop restarting it. */
    @Override
    public void close() throws InterruptedException {
        closed = true;
        supervisor.interrupt();
        supervisor.join(5000);
        Process p = socat;
        if (p != null) {
            p.destroy();
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }
}
