package org.kheperasim.sim.gui;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.replay.RobotSeries;
import org.kheperasim.sim.replay.SeriesRecorder;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.serve.ProtocolServer;
import org.kheperasim.sim.serve.ServedArena;
import org.kheperasim.sim.serve.ServedRobot;

/**
 * "Serve this robot": the arena as drawn, each robot answering the Khepera protocol over TCP on a
 * free loopback port in real time, driven by any Khepera client. While it serves, the window shows it.
 */
final class ServeControls implements SnapshotSource {
    private final EditorModel model;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunChoices choices;
    private final ViewFeed feed;
    private final List<ProtocolServer> servers = new ArrayList<>();
    private final AtomicReference<Snapshot> latest = new AtomicReference<>();
    private final TrailRecorder trail = new TrailRecorder();
    private SeriesRecorder series = new SeriesRecorder();
    private volatile ServedArena served;

    ServeControls(EditorModel model, ConsolePanel console, StatusBar status, RunChoices choices, ViewFeed feed) {
        this.model = model;
        this.console = console;
        this.status = status;
        this.choices = choices;
        this.feed = feed;
    }

    @Override
    public Snapshot snapshot() {
        return latest.get();
    }

    @Override
    public String state() {
        return served != null ? "serving" : "stopped serving";
    }

    @Override
    public float[] trail(int robot) {
        return trail.trail(robot);
    }

    @Override
    public RobotSeries series(int robot) {
        return series.series(robot);
    }

    /** @return true while serving */
    boolean serving() {
        return served != null;
    }

    /** @return the protocol servers while serving, one per robot */
    List<ProtocolServer> servers() {
        return List.copyOf(servers);
    }

    /** Serve the arena as drawn, or stop serving. */
    void toggle() {
        if (served != null) {
            stop();
            return;
        }
        long seed = choices.seed != null ? choices.seed : Simulation.randomSeed();
        ServedArena world = new ServedArena(model.arena(), choices.settings, seed, 1.0);
        trail.clear();
        series = new SeriesRecorder();
        latest.set(null);
        world.addListener(latest::set, 20 * Engine.TICK_NANOS);
        world.addListener(trail, 20 * Engine.TICK_NANOS);
        world.addListener(series, 100 * Engine.TICK_NANOS);
        try {
            for (ServedRobot robot : world.robots()) {
                servers.add(ProtocolServer.start(robot, 0));
            }
        } catch (IOException e) {
            servers.forEach(ProtocolServer::close);
            servers.clear();
            world.close();
            console.error("Cannot serve the robots: " + e.getMessage()
                    + ". Free a loopback port or use 'khepera-sim serve --port N'.");
            return;
        }
        served = world;
        feed.show(this);
        for (int i = 0; i < servers.size(); i++) {
            String who = servers.size() == 1 ? "server: " : "server of robot " + i + ": ";
            servers.get(i).addListener(ev -> console.note(who + ev.text()));
        }
        boolean one = servers.size() == 1;
        String urls = one ? servers.get(0).url()
                : String.join(", ", servers.stream().map(ProtocolServer::url).toList());
        console.note((one ? "Serving this robot at "
                : "Serving these " + servers.size() + " robots (robot 0, 1, ...) at ")
                + urls + " (seed " + seed + "). Drive " + (one ? "it" : "each")
                + " with any Khepera client, e.g. java -jar"
                + " robot-link/target/khepera-link.jar run --port " + servers.get(0).url()
                + " --controller WallFollower. Run > Stop serving ends it.");
        status.show("Serving at " + urls, false);
    }

    /** Stop serving: the robots' wheels stop and the clients are disconnected. */
    void stop() {
        ServedArena r = served;
        if (r == null) {
            return;
        }
        // Said while the served world still sets the console's clock: the note has its time.
        console.note("Stopped serving; the robots' wheels were stopped.");
        served = null;
        servers.forEach(ProtocolServer::close);
        servers.clear();
        r.close();
        feed.back(this);
        status.show("Stopped serving", false);
    }
}
