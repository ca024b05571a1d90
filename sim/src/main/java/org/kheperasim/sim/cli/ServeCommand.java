package org.kheperasim.sim.cli;

import java.io.PrintStream;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.serve.ProtocolServer;
import org.kheperasim.sim.serve.PtyBridge;
import org.kheperasim.sim.serve.ServedRobot;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code serve}: a simulated robot that answers the Khepera protocol over TCP (and a pty). */
@Command(name = "serve", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Serve a simulated Khepera over its own serial protocol, so any Khepera client drives it.",
            "Runs in real time until Ctrl-C (or --seconds). One client at a time; the robot stops when it leaves.",
            "Example: java -jar khepera-link.jar run --port tcp://127.0.0.1:4000 --controller WallFollower"})
final class ServeCommand implements Callable<Integer> {

    @Option(names = "--arena", required = true, paramLabel = "FILE",
            description = "an arena file, or a bundled arena: lab, maze, two-rooms; the robot starts at its first pose")
    String arena;

    @Option(names = "--port", paramLabel = "N", defaultValue = "" + ProtocolServer.DEFAULT_PORT,
            description = "TCP port (default: ${DEFAULT-VALUE}; 0 = any free port, printed)")
    int port;

    @Option(names = "--bind", paramLabel = "ADDRESS",
            description = "listen on this address instead of loopback (127.0.0.1), e.g. 0.0.0.0: lets OTHER computers drive the robot")
    String bind;


    @Option(names = "--speed", paramLabel = "X", defaultValue = "1", converter = CliNumbers.PositiveDecimal.class,
            description = "simulated seconds per real second (default ${DEFAULT-VALUE}: the real robot's pace; reply timing scales too)")
    double speed;

    @Option(names = "--seed", paramLabel = "N", converter = CliNumbers.AnyLong.class, description = "the seed of the robot's noise (default: a new one, printed)")
    Long seed;


    @Mixin
    SettingsOptions settingsOptions = new SettingsOptions();

    @Option(names = "--pty", paramLabel = "PATH",
            description = "also make a pseudo-terminal at PATH for serial-only clients (starts socat; prints the command if it is missing)")
    Path pty;

    @Option(names = "--idle-timeout", paramLabel = "SECONDS", defaultValue = "60",
            description = "let a client go after SECONDS without a command, so none holds the robot forever; 0 = never (default: ${DEFAULT-VALUE})")
    double idleTimeout;

    @Option(names = "--seconds", paramLabel = "T", converter = CliNumbers.PositiveSeconds.class, description = "stop after T real seconds (default: run until Ctrl-C)")
    Double seconds;

    @Override
    public Integer call() throws Exception {
        Settings settings = settingsOptions.settings();
        long runSeed = seed != null ? seed : Simulation.randomSeed();
        Arena a = ArenaFormat.resolve(arena);
        InetAddress address = bind == null ? InetAddress.getLoopbackAddress() : InetAddress.getByName(bind);
        PrintStream out = System.out;
        ServedRobot robot = new ServedRobot(a, settings, runSeed, speed);
        ProtocolServer server;
        try {
            if (!(idleTimeout >= 0 && idleTimeout <= 86_400)) {
                throw new IllegalArgumentException("--idle-timeout " + idleTimeout + " must lie in 0..86400 seconds (0 = never)");
            }
            server = ProtocolServer.start(robot, address, port).idleTimeout((long) (idleTimeout * 1000));
        } catch (Exception e) {
            robot.close();
            throw e;
        }
        server.addListener(e -> out.println(e.text()));
        CountDownLatch stopped = new CountDownLatch(1);
        PtyBridge bridge = null;
        Thread hook = new Thread(() -> {
            server.close();
            robot.close();
            stopped.countDown();
        }, "serve-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            out.println("seed " + runSeed);
            out.printf(Locale.ROOT, "serving a simulated Khepera in arena %s at %s (%d baud timing, speed x%s)%n",
                    a.name(), server.url(), robot.timing().baud(), fmt(speed));
            if (server.isExposed()) {
                out.println("WARNING: listening on " + server.bindAddress().getHostAddress() + ":" + server.port()
                        + ": any computer that can reach this one can drive the robot. There is no password.");
            }
            out.println("connect: java -jar robot-link/target/khepera-link.jar run --port " + server.url()
                    + " --controller WallFollower");
            if (pty != null) {
                if (PtyBridge.socatInstalled()) {
                    bridge = PtyBridge.start(pty, server.port(), out::println);
                    out.println("pty: " + pty + " (socat: " + String.join(" ", bridge.commandLine()) + ")");
                    out.println("connect: java -jar robot-link/target/khepera-link.jar run --port " + pty
                            + " --controller WallFollower");
                } else {
                    out.println("socat is not installed, so no pty was made. Install it, or run yourself:");
                    out.println("  " + String.join(" ", PtyBridge.command(pty, server.port())));
                }
            }
            out.println("Ctrl-C stops the server (the robot stops first).");
            out.flush();
            if (seconds != null) {
                stopped.await((long) (seconds * 1000), TimeUnit.MILLISECONDS);
            } else {
                stopped.await();
            }
        } finally {
            if (bridge != null) {
                bridge.close();
            }
            server.close();
            robot.close();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // The hook is running: it closes the same things.
            }
        }
        out.println("server stopped after " + server.commandsAnswered() + " commands");
        return 0;
    }

    private static String fmt(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
