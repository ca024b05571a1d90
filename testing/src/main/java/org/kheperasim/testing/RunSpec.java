package org.kheperasim.testing;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SortedMap;
import org.kheperasim.sim.testkit.KitArena;
import org.kheperasim.sim.testkit.KitEdits;
import org.kheperasim.sim.testkit.KitRunSpec;
import org.kheperasim.sim.testkit.KitSettings;

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
record RunSpec(String arenaArg, KitArena arena, List<String> controllers, List<KitSettings> settings,
        List<Path> classpath, long seed, double seconds, long sampleMillis, boolean trusted, double hangTimeoutSeconds,
        KitEdits edits) {

    /** The default hang timeout, as {@code run}'s. */
    static final double DEFAULT_HANG_TIMEOUT = 5;

    RunSpec {
        controllers = List.copyOf(controllers);
        settings = List.copyOf(settings);
        classpath = List.copyOf(classpath);
        if (controllers.size() != arena.robotCount() || settings.size() != controllers.size()) {
            throw new IllegalArgumentException("the arena " + arena.name() + " has " + arena.robotCount()
                    + " robots, but " + controllers.size() + " controllers were given");
        }
    }

    /** @return this run as the simulator's test kit takes it */
    KitRunSpec kit() {
        return new KitRunSpec(arena, controllers, settings, classpath, seed, seconds, sampleMillis, trusted,
                hangTimeoutSeconds, edits);
    }

    /**
     * @return the {@code khepera-sim run} command line that makes the same run (add {@code --trace FILE} for its trace)
     */
    String commandLine() {
        List<String> args = new ArrayList<>(
                List.of("java", "-jar", "khepera-sim.jar", "run", "--arena", quote(arenaArg)));
        if (!classpath.isEmpty()) {
            args.add("--classpath");
            args.add(quote(String.join(File.pathSeparator, classpath.stream().map(RunSpec::shown).toList())));
        }
        args.addAll(List.of("--controller", controllers.get(0), "--seed", Long.toString(seed), "--seconds",
                number(seconds)));
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
