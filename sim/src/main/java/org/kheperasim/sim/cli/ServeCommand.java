package org.kheperasim.sim.cli;

import java.io.PrintStream;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.serve.ProtocolServer;
import org.kheperasim.sim.serve.PtyBridge;
import org.kheperasim.sim.serve.ServedArena;
import org.kheperasim.sim.serve.ServedRobot;
import org.kheperasim.sim.text.Shown;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code serve}: a simulated robot that answers the Khepera protocol over TCP (and a pty). */
@Command(name = "serve", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Serve a simulated Khepera over its own serial protocol, so any Khepera client drives it.",
            "Runs in real time until Ctrl-C (or --seconds). One client at a time per robot; a robot stops when its"
                    + " client leaves.",
            "An arena with several robots serves each on its own port (and pty PATH-1, PATH-2, ...); they meet"
                    + " in one arena.",
            "Example: java -jar khepera-link.jar run --port tcp://127.0.0.1:4000 --controller WallFollower"})
final class ServeCommand implements Callable<Integer> {

    @Option(names = "--arena", required = true, paramLabel = "FILE",
            description = "an arena file, or a bundled arena (see list); each of its robots is served on its own port"
                    + " (port, port+1, ...)")
    String arena;

    @Option(names = "--robot-file", paramLabel = "FILE",
            description = "the robot for the arena's robot lines that name none: a robot file or a bundled"
                    + " robot (see robots)")
    String robotFile;

    @Option(names = "--port", paramLabel = "N", defaultValue = "" + ProtocolServer.DEFAULT_PORT,
            description = "TCP port (default: ${DEFAULT-VALUE}; 0 = any free port, printed)")
    int port;

    @Option(names = "--bind", paramLabel = "ADDRESS",
            description = "listen on this address instead of loopback (127.0.0.1), e.g. 0.0.0.0: lets OTHER computers"
                    + " drive the robot")
    String bind;


    @Option(names = "--speed", paramLabel = "X", defaultValue = "1", converter = CliNumbers.PositiveDecimal.class,
            description = "simulated seconds per real second (default ${DEFAULT-VALUE}: the real robot's pace; reply"
                    + " timing scales too)")
    double speed;

    @Option(names = "--seed", paramLabel = "N", converter = CliNumbers.AnyLong.class,
            description = "the seed of the robot's noise (default: a new one, printed)")
    Long seed;


    @Mixin
    SettingsOptions settingsOptions = new SettingsOptions();

    @Option(names = "--pty", paramLabel = "PATH",
            description = "also make a pseudo-terminal at PATH for serial-only clients (Linux): a program"
                    + " that opens PATH as a serial port drives the robot")
    Path pty;

    @Option(names = "--dialect", paramLabel = "NAME",
            description = "answer in this robot's protocol: khepera1, khepera2 or epuck (letters, replies, errors;"
                    + " values are passed through as counts). Default: each robot's own, from its robot file")
    String dialect;

    @Option(names = "--idle-timeout", paramLabel = "SECONDS", defaultValue = "60",
            description = "let a client go after SECONDS without a command, so none holds the robot forever; 0 = never"
                    + " (default: ${DEFAULT-VALUE})")
    double idleTimeout;

    @Option(names = "--seconds", paramLabel = "T", converter = CliNumbers.PositiveSeconds.class,
            description = "stop after T real seconds (default: run until Ctrl-C)")
    Double seconds;

    @Option(names = "--sandbox",
            description = "serve from an operating-system sandbox, as grade runs its runs: only the Java"
            + " runtime, the simulator and the arena visible, limits on processes, files and memory; the"
            + " network stays (the clients must reach the robot). Linux, bubblewrap; not with --pty (see"
            + " docs/grading.md)")
    boolean sandbox;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (sandbox) {
            if (pty != null) {
                throw new IllegalArgumentException("--pty " + pty
                        + " cannot be used with --sandbox: the pseudo-terminal needs"
                        + " socat, which the sandbox does not hold; leave one of them out");
            }
            Path arenaFile = Path.of(arena);
            List<Path> read = new java.util.ArrayList<>(java.nio.file.Files.isRegularFile(arenaFile)
                    ? List.of(arenaFile) : List.of());
            read.addAll(RobotFiles.files(arena, robotFile));
            return org.kheperasim.sim.sandbox.Reexec.run("serve", Sandboxed.argsAfter(spec, "serve"), read,
                    List.of(), true,
                    org.kheperasim.sim.sandbox.BoxLimits.forCommand(ArenaFormat.resolve(arena).robots().size()), 10);
        }
        Dialect served = dialect == null ? null : Dialect.named(dialect);
        Settings settings = settingsOptions.settings();
        long runSeed = seed != null ? seed : Simulation.randomSeed();
        Arena a = RobotFiles.arena(arena, robotFile);
        InetAddress address = bind == null ? InetAddress.getLoopbackAddress() : InetAddress.getByName(bind);
        PrintStream out = System.out;
        if (!(idleTimeout >= 0 && idleTimeout <= 86_400)) {
            throw new IllegalArgumentException("--idle-timeout " + idleTimeout
                    + " must lie in 0..86400 seconds (0 = never)");
        }
        int count = a.robots().size();
        if (count > 1 && port != 0 && (port < 0 || port + count - 1 > 65535)) {
            throw new IllegalArgumentException("--port " + port + ": the arena's " + count
                    + " robots need ports " + port
                    + ".." + (port + count - 1)
                    + ", which must lie in 1..65535; give a lower --port, or 0 for any free ports");
        }
        ServedArena world = new ServedArena(a, settings, runSeed, speed).dialect(served);
        List<ServedRobot> robots = world.robots();
        List<ProtocolServer> servers = new ArrayList<>();
        List<PtyBridge> bridges = new ArrayList<>();
        try {
            for (int i = 0; i < robots.size(); i++) {
                ProtocolServer server;
                try {
                    server = ProtocolServer.start(robots.get(i), address, port == 0 ? 0 : port + i);
                } catch (java.io.IOException e) {
                    if (robots.size() == 1) {
                        throw e;
                    }
                    throw new java.io.IOException("robot " + i + " (--port " + port + " + " + i + "): "
                            + e.getMessage(), e);
                }
                server.idleTimeout((long) (idleTimeout * 1000));
                String who = robots.size() == 1 ? "" : "robot " + i + ": ";
                server.addListener(e -> out.println(who + Shown.line(e.text())));
                servers.add(server);
            }
        } catch (Exception e) {
            servers.forEach(ProtocolServer::close);
            world.close();
            throw e;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            servers.forEach(ProtocolServer::close);
            world.close();
            stopped.countDown();
        }, "serve-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            out.println("seed " + runSeed);
            Dialect shown = served != null ? served : Dialect.named(a.robotType(0).dialect());
            if (shown != Dialect.named(Dialect.DEFAULT)) {
                out.println("dialect " + shown.name() + ": the robots answer as " + shown.robot() + "s do"
                        + " (connect with khepera-link --dialect " + shown.name() + ")");
            }
            if (robots.size() == 1) {
                out.printf(Locale.ROOT, "serving a simulated Khepera in arena %s at %s (%d baud timing, speed x%s)%n",
                        a.name(), servers.get(0).url(), robots.get(0).timing().baud(), fmt(speed));
            } else {
                out.printf(Locale.ROOT,
                        "serving %d simulated Kheperas that meet in arena %s (%d baud timing, speed x%s),"
                        + " each on its own port:%n", robots.size(), a.name(),
                        robots.get(0).timing().baud(), fmt(speed));
                for (int i = 0; i < robots.size(); i++) {
                    out.printf(Locale.ROOT, "robot %d at %s, starting at (%.0f, %.0f) mm%n", i, servers.get(i).url(),
                            a.robots().get(i).x(), a.robots().get(i).y());
                }
            }
            if (servers.get(0).isExposed()) {
                out.println("WARNING: listening on " + servers.get(0).bindAddress().getHostAddress()
                        + ": any computer that"
                        + " can reach this one can drive the robots. There is no password.");
            }
            out.println("connect: java -jar robot-link/target/khepera-link.jar run --port " + servers.get(0).url()
                    + " --controller WallFollower");
            if (pty != null) {
                for (int i = 0; i < servers.size(); i++) {
                    java.nio.file.Path path = i == 0 ? pty : pty.resolveSibling(pty.getFileName() + "-" + i);
                    PtyBridge bridge = PtyBridge.start(path, servers.get(i).port(),
                            note -> out.println(Shown.line(note)));
                    bridges.add(bridge);
                    out.println((servers.size() == 1 ? "" : "robot " + i + " ") + "pty: " + path + " ("
                            + bridge.device()
                            + "; open it as a serial port)");
                }
                out.println("connect: java -jar robot-link/target/khepera-link.jar run --port " + pty
                        + " --controller WallFollower");
            }
            out.println("Ctrl-C stops the server (the robots stop first).");
            out.flush();
            if (seconds != null) {
                stopped.await((long) (seconds * 1000), TimeUnit.MILLISECONDS);
            } else {
                stopped.await();
            }
        } finally {
            for (PtyBridge b : bridges) {
                b.close();
            }
            servers.forEach(ProtocolServer::close);
            world.close();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // The hook is running: it closes the same things.
            }
        }
        long answered = servers.stream().mapToLong(ProtocolServer::commandsAnswered).sum();
        out.println("server stopped after " + answered + " commands");
        return 0;
    }

    private static String fmt(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
