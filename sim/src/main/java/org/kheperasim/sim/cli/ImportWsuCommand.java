package org.kheperasim.sim.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.sim.files.AtomicFiles;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.wsu.WsuWorld;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code import-wsu}: a world file of the original WSU Khepera Simulator, written as an arena file. */
@Command(name = "import-wsu", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Convert a world (map) file of the original WSU Khepera Simulator into an arena file.",
            "The run and gui commands also open WSU world files directly; this writes one you can read and edit.",
            "Example: java -jar khepera-sim.jar import-wsu maze -o maze.arena"})
final class ImportWsuCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "MAP", description = "the WSU world file")
    Path map;

    @Option(names = {"-o", "--output"}, paramLabel = "NAME.arena",
            description = "where to write the arena (default: the map's name with .arena, in the current folder);"
                    + " the arena is named after this file")
    Path output;

    @Option(names = "--profile", paramLabel = "PROFILE", defaultValue = "robot",
            description = "robot (the default: the arena's robot is the real Khepera) or wsu (its robot line names the"
                    + " bundled robot wsu, which runs with the wsu profile: the original simulator's behaviour, as"
                    + " --set profile=wsu gives; see docs/wsu-migration.md)")
    String profile;

    @Override
    public Integer call() {
        if (!Files.isRegularFile(map)) {
            throw new IllegalArgumentException("no WSU world file " + map + "; give the path of a map saved by the"
                    + " WSU Khepera Simulator");
        }
        if (!profile.equals("robot") && !profile.equals("wsu")) {
            throw new IllegalArgumentException("--profile " + profile
                    + ": give robot (the real Khepera, the default) or wsu"
                    + " (the original simulator's behaviour)");
        }
        Path target = output != null ? output : Path.of(WsuWorld.nameOf(map) + ArenaFormat.EXTENSION);
        if (Files.exists(target) && sameFile(target, map)) {
            throw new IllegalArgumentException("-o " + target + " is the WSU world file itself; give another name,"
                    + " e.g. -o " + WsuWorld.nameOf(map) + ArenaFormat.EXTENSION);
        }
        List<String> warnings = new ArrayList<>();
        WsuWorld.Imported imported = WsuWorld.importWorld(map, warnings::add);
        Arena read = imported.arena();
        Arena arena = new Arena(WsuWorld.nameOf(target), read.width(), read.height(), read.robots(), read.walls(),
                read.lights(), read.caps(), read.regions());
        if (profile.equals("wsu")) {
            arena = arena.withDefaultRobot(org.kheperasim.sim.arena.RobotKind.of("wsu"));
        }
        for (String w : warnings) {
            System.err.println(map + ": warning: " + w);
        }
        writeAtomically(target, header(imported, warnings) + ArenaFormat.write(arena));
        Pose p = arena.robots().get(0);
        System.out.printf(Locale.ROOT, "wrote %s from %s: %s; robot at (%.1f, %.1f) mm facing east%s%n", target, map,
                contents(imported), p.x(), p.y(),
                warnings.isEmpty() ? "" : "; " + warnings.size() + " warning(s) above");
        return 0;
    }

    private static String contents(WsuWorld.Imported w) {
        return String.format(Locale.ROOT, "%d walls, %d caps, %d balls, %d lights in the file; %d walls in the arena"
                + " (the 4 border walls the original always has, then the file's walls, joined where they continue"
                + " one another)", w.walls(), w.caps(), w.balls(), w.lights(), w.arena().walls().size());
    }

    private String header(WsuWorld.Imported imported, List<String> warnings) {
        StringBuilder sb = new StringBuilder();
        sb.append("# Imported from the WSU Khepera Simulator world file ").append(map.getFileName())
                .append(" by khepera-sim import-wsu (see docs/wsu-migration.md).\n");
        sb.append("# 500 x 500 px panel -> 1219.2 mm square, 1 px = 2.4384 mm, y flipped to point up;"
                + " balls are caps.\n");
        sb.append("# ").append(contents(imported)).append(".\n");
        if (profile.equals("wsu")) {
            sb.append("# The robot is 'wsu': it behaves as the original simulator's (the wsu profile,"
                    + " docs/wsu-migration.md).\n");
        }
        for (String w : warnings) {
            sb.append("# warning: ").append(w).append('\n');
        }
        return sb.toString();
    }

    private static boolean sameFile(Path a, Path b) {
        try {
            return Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }

    /** The one atomic save: a reader never sees half a file, a link stays a link, the file keeps its mode. */
    private static void writeAtomically(Path file, String text) {
        try {
            AtomicFiles.write(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write arena file " + file + ": " + e.getMessage(), e);
        }
    }
}
