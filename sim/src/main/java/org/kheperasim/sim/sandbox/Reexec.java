package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * {@code run --sandbox} and {@code serve --sandbox}: the same command again, in a {@link Box}, with
 * the terminal's input and output, and its exit status. The box shows the simulator's classpath (at its
 * real location, {@link OwnClasspath}, however the jar was named), the
 * files the command reads (the arena, the controller's classpath, a settings or edits file) and the
 * file it writes (the trace), nothing else. Stopping this process (Ctrl-C, SIGTERM) stops the run in
 * the box the same way, so it still finishes its trace and prints its result.
 */
public final class Reexec {
    private Reexec() {
    }

    /**
     * @param command     the subcommand, e.g. {@code run}
     * @param args        its arguments, without {@code --sandbox}
     * @param readOnly    files and folders the command reads
     * @param writable    files the command writes (made empty now, if missing)
     * @param network     true to keep the network ({@code serve}, whose clients must reach it)
     * @param limits      the box's limits
     * @param stopSeconds how long a stop may take before the box is killed, s
     * @return the command's exit status in the box
     * @throws IllegalArgumentException if no box can be made here, saying why and what to do
     */
    public static int run(String command, List<String> args, List<Path> readOnly, List<Path> writable, boolean network,
            BoxLimits limits, double stopSeconds) {
        BoxProbe.unavailable().ifPresent(reason -> {
            throw new IllegalArgumentException(command + " --sandbox runs the controller in a bubblewrap sandbox, but "
                    + reason + "; or leave --sandbox out (only for code you trust). See docs/grading.md,"
                    + " \"The sandbox\".");
        });
        List<Path> read = new ArrayList<>(readOnly);
        read.addAll(OwnClasspath.entries()); // at their real paths: the box runs in a folder of its own
        ClassArchive.current().ifPresent(read::add);
        List<Path> write = new ArrayList<>();
        try {
            for (Path w : writable) {
                Path abs = w.toAbsolutePath();
                Files.createDirectories(abs.getParent());
                Files.write(abs, new byte[0]);
                Box.handOver(abs, 0);
                write.add(abs);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot make " + e.getMessage() + " for the sandboxed run to write", e);
        }
        List<String> java = new ArrayList<>(List.of("--enable-native-access=ALL-UNNAMED", "-Djava.awt.headless=true",
                "-Xmx" + (limits.memoryBytes() / (1L << 20) - 768) + "m"));
        System.getProperties().stringPropertyNames().stream().filter(k -> k.startsWith("kheperasim.")).sorted()
                .forEach(k -> java.add("-D" + k + "=" + System.getProperty(k)));
        java.addAll(ClassArchive.jvmOptions());
        java.addAll(List.of("-cp", OwnClasspath.asOption(), "org.kheperasim.sim.cli.Main", command));
        java.addAll(args);
        List<String> cmd = Box.command(new Box.Spec(read, write, null, network, limits, 0), java);
        Process p;
        try {
            p = new ProcessBuilder(cmd).inheritIO().start();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot start bubblewrap: " + e.getMessage(), e);
        }
        Thread stop = new Thread(() -> stop(p, stopSeconds), "khepera-sandbox-stop");
        Runtime.getRuntime().addShutdownHook(stop);
        try {
            return p.waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroyForcibly();
            return 143;
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stop);
            } catch (IllegalStateException shuttingDown) {
                // the hook is stopping the box
            }
        }
    }

    /**
     * The command in the box runs in a session of its own, so a Ctrl-C reaches only this process:
     * pass it on as SIGTERM to the JVM in the box (which stops its run and reports it), then kill the
     * box if it has not ended in time.
     */
    private static void stop(Process box, double seconds) {
        box.descendants().filter(h -> h.info().command().map(c -> c.endsWith("/java")).orElse(false))
                .forEach(ProcessHandle::destroy);
        try {
            if (!box.waitFor((long) (seconds * 1000), TimeUnit.MILLISECONDS)) {
                box.destroyForcibly();
            }
        } catch (InterruptedException e) {
            box.destroyForcibly();
        }
    }
}
