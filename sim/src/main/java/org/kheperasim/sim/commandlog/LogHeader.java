package org.kheperasim.sim.commandlog;

import java.util.List;

/**
 * What a command log says about the run it comes from: enough to set the same run up again without
 * its controllers. A reader of the log checks these against what it asked for (see
 * {@link OpenLoopReplay.Run}); the log alone never decides the seed, the settings or the length.
 *
 * @param seed         the run's seed
 * @param arena        the arena's name and hash as the trace header writes them ({@code maze sha256=…})
 * @param endNanos     where the run was to end, simulated ns
 * @param sampleMillis the trace's sample period, ms
 * @param robots       one per robot, in the engine's order
 */
public record LogHeader(long seed, String arena, long endNanos, long sampleMillis, List<Robot> robots) {
    /** The first line of every command log (version 1). */
    public static final String MAGIC = "khepera-commands 1";

    /**
     * @param controllerClass the controller's class name, as the trace header writes it
     * @param name            the robot's name in reports (the class's simple name, {@code Name#i} with several)
     * @param settings        its settings as {@code Settings.describe()} writes them
     * @param mode            where its controller ran ({@code SimRobot.controlMode()}): through the link or on the
     *     robot
     */
    public record Robot(String controllerClass, String name, String settings, String mode) {
    }

    /** Copies the list. */
    public LogHeader {
        robots = List.copyOf(robots);
    }

    /**
     * @param session      a run, set up
     * @param endNanos     where it ends, simulated ns
     * @param sampleMillis its trace's sample period, ms
     * @return the header of its command log
     */
    public static LogHeader of(org.kheperasim.sim.run.RunSession session, long endNanos, long sampleMillis) {
        java.util.List<Robot> robots = new java.util.ArrayList<>();
        var engineRobots = session.engine().robots();
        var hosts = session.hosts();
        for (int i = 0; i < engineRobots.size(); i++) {
            robots.add(new Robot(hosts.get(i).type().getName(), engineRobots.get(i).name(),
                    engineRobots.get(i).settings().describe(), engineRobots.get(i).controlMode()));
        }
        return new LogHeader(session.seed(), session.arena().name() + " sha256="
                + org.kheperasim.sim.arena.ArenaFormat.sha256(session.arena()), endNanos, sampleMillis, robots);
    }

    /** @return the header as lines, each ending in a newline */
    String text() {
        StringBuilder sb = new StringBuilder(MAGIC).append('\n');
        sb.append("seed ").append(seed).append('\n');
        sb.append("arena ").append(arena).append('\n');
        sb.append("end-ns ").append(endNanos).append('\n');
        sb.append("sample-ms ").append(sampleMillis).append('\n');
        sb.append("robots ").append(robots.size()).append('\n');
        for (int i = 0; i < robots.size(); i++) {
            Robot r = robots.get(i);
            sb.append("robot ").append(i).append(' ').append(r.controllerClass()).append(' ')
                    .append(r.name()).append('\n');
            sb.append("settings ").append(i).append(' ').append(r.settings()).append('\n');
            sb.append("mode ").append(i).append(' ').append(r.mode()).append('\n');
        }
        return sb.toString();
    }
}
