package org.kheperasim.sim.serve;

import java.io.IOException;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;

/** A served robot and its server, on a 1219 mm arena with the robot at (300, 600) facing +x. */
final class Served implements AutoCloseable {
    final ServedRobot robot;
    final ProtocolServer server;

    Served(String body, Settings settings, double speed) throws IOException {
        String text = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0\n" + body;
        robot = new ServedRobot(ArenaFormat.parse(text, "t.arena"), settings, 1, speed);
        server = ProtocolServer.start(robot, 0);
    }

    LineClient client() throws IOException {
        return new LineClient(server.port());
    }

    @Override
    public void close() {
        server.close();
        robot.close();
    }
}
