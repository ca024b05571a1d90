package org.kheperasim.testing;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SortedMap;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.run.Simulation;

/**
 * Everything that decides a run, as {@code khepera-sim run}'s options do: the arena, each robot's
 * controller and settings, the seed, the duration, the sample period, and for a window's recording its
 * arena edits. A run made from the same spec is the same run.
 *
 * @param arenaArg the arena as the user named it (a bundled name or a file), for the command line
 * @param arena the arena
 * @param controllers each robot's controller class name (a bundled controller's simple name or a class name)
 * @param settings each robot's settings
 * @param classpath the folders and jars the controllers' classes come from (empty for bundled ones)
 * @param seed the seed
 * @param seconds simulated seconds to run
 * @param sampleMillis the trace's sample period, whole ms
 * @param trusted true to run the controllers uncontained ({@code --trusted})
 * @param hangTimeoutSeconds real seconds without an API call after which a controller counts as hung
 * @param edits a window's arena edits with their times, or null
 */
record RunSpec(String arenaArg, Arena arena, List<String> controllers, List<Settings> settings, List<Path> classpath,
        long seed, double seconds, long sampleMillis, boolean trusted, double hangTimeoutSeconds, EditLog edits) {

    /** The default hang timeout, as {@code run}'s. */
    static final double DEFAULT_HANG_TIMEOUT = 5;

    RunSpec {
        controllers = List.copyOf(controllers);
        settings = List.copyOf(settings);
        classpath = List.copyOf(classpath);
        if (controllers.size() != arena.robots().size() || settings.size() != controllers.size()) {
            throw new IllegalArgumentException("the arena " + arena.name() + " has " + arena.robots().size()
                    + " robots, but " + controllers.size() + " controllers were given");
        }
    }

    /**
     * @param trace where the trace goes
     * @param capture what else the run tells
     * @return the simulator's builder for this run
     */
    Simulation.Builder simulation(java.io.Writer trace, RunCapture capture) {
        Simulation.Builder b = Simulation.builder().arena(arena).controller(controllers.get(0)).classpath(classpath)
                .seed(seed).seconds(seconds).settings(settings.get(0)).sampleMillis(sampleMillis).trusted(trusted)
                .hostOptions(HostOptions.defaults().withHangTimeout((long) (hangTimeoutSeconds * 1e9)))
                .trace(trace).listener(capture, sampleMillis).console(capture);
        for (int i = 1; i < controllers.size(); i++) {
            boolean ownController = !controllers.get(i).equals(controllers.get(0));
            boolean ownSettings = !settings.get(i).equals(settings.get(0));
            if (ownController || ownSettings) {
                b.robot(i, ownController ? controllers.get(i) : null, ownSettings ? settings.get(i) : null);
            }
        }
        if (edits != null) {
            b.edits(edits);
        }
        return b;
    }

    /** @return the {@code khepera-sim run} command line that makes the same run (add {@code --trace FILE} for its trace) */
    String commandLine() {
        List<String> args = new ArrayList<>(List.of("java", "-jar", "khepera-sim.jar", "run", "--arena", quote(arenaArg)));
        if (!classpath.isEmpty()) {
            args.add("--classpath");
            args.add(quote(String.join(File.pathSeparator, classpath.stream().map(RunSpec::shown).toList())));
        }
        args.addAll(List.of("--controller", controllers.get(0), "--seed", Long.toString(seed), "--seconds", number(seconds)));
        settings.get(0).overrides().forEach((k, v) -> args.addAll(List.of("--set", k + "=" + v)));
        SortedMap<String, String> base = settings.get(0).overrides();
        for (int i = 1; i < controllers.size(); i++) {
            if (!controllers.get(i).equals(controllers.get(0))) {
                args.addAll(List.of("--robot", i + ":controller=" + controllers.get(i)));
            }
            for (Map.Entry<String, String> e : settings.get(i).overrides().entrySet()) {
                if (!e.getValue().equals(base.get(e.getKey()))) {
                    args.addAll(List.of("--robot", i + ":" + e.getKey() + "=" + e.getValue()));
                }
            }
        }
        if (sampleMillis != 50) {
            args.addAll(List.of("--sample-ms", Long.toString(sampleMillis)));
        }
        if (trusted) {
            args.add("--trusted");
        }
        if (hangTimeoutSeconds != DEFAULT_HANG_TIMEOUT) {
            args.addAll(List.of("--hang-timeout", number(hangTimeoutSeconds)));
        }
        return String.join(" ", args);
    }

    /** A path as a message shows it: relative to the working folder when it lies inside it. */
    static String shown(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        Path here = Path.of("").toAbsolutePath();
        return abs.startsWith(here) && !abs.equals(here) ? here.relativize(abs).toString() : abs.toString();
    }

    private static String quote(String s) {
        return s.matches("[\\w./:=@+,-]+") ? s : "'" + s.replace("'", "'\\''") + "'";
    }

    static String number(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : String.format(Locale.ROOT, "%s", d);
    }
}
