package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.sandbox.ClassArchive;

/**
 * The warm JVM's command line: the user's JVM options, then the archive's, then the same jar and
 * arguments; the quick compiler only for a run of at most 600 s that says so; none at all when the
 * command line was not {@code java [options] -jar JAR} or chose an archive itself.
 */
class WarmStartTest {
    private static final Path ARCHIVE = Path.of("/opt/k/khepera-sim.jsa");
    private static final String[] RUN = {"run", "--arena", "maze", "--controller", "WallFollower", "--seconds", "60"};

    @Test
    void theWarmJvmGetsTheUsersOptionsTheArchiveAndTheSameCommand() {
        List<String> cmd = WarmStart.command(jvm("-Xmx1g", "-Dx=y", "-jar", "k.jar"), ARCHIVE, RUN);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> expected = new ArrayList<>(List.of(java, "-Xmx1g", "-Dx=y"));
        expected.addAll(ClassArchive.jvmOptions(ARCHIVE));
        expected.addAll(List.of(WarmStart.QUICK_COMPILER, "-D" + WarmStart.STARTED + "=true", "-jar", "k.jar"));
        expected.addAll(List.of(RUN));
        assertEquals(expected, cmd);
    }

    @Test
    void onlyAShortRunGetsTheQuickCompilerAndNotWhenTheUserChoseOne() {
        assertTrue(WarmStart.shortRun(RUN));
        assertTrue(WarmStart.shortRun(new String[] {"run", "--seconds=600"}));
        assertFalse(WarmStart.shortRun(new String[] {"run", "--seconds", "601"}));
        assertFalse(WarmStart.shortRun(new String[] {"run", "--arena", "maze"}), "the arena's time, 600 s or more");
        assertFalse(WarmStart.shortRun(new String[] {"run", "--seconds", "sixty"}));
        assertFalse(WarmStart.shortRun(new String[] {"evaluate", "--seconds", "60"}), "evaluate is for many runs");
        List<String> chosen = WarmStart.command(jvm("-XX:TieredStopAtLevel=4", "-jar", "k.jar"), ARCHIVE, RUN);
        assertFalse(chosen.contains(WarmStart.QUICK_COMPILER), chosen.toString());
        List<String> longRun = WarmStart.command(jvm("-jar", "k.jar", "run", "--seconds", "3600"), ARCHIVE,
                new String[] {"run", "--seconds", "3600"});
        assertFalse(longRun.contains(WarmStart.QUICK_COMPILER), longRun.toString());
        assertTrue(longRun.contains("-XX:SharedArchiveFile=" + ARCHIVE), longRun.toString());
    }

    @Test
    void onlyASmallGradingGetsTheQuickCompiler(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        for (int i = 0; i < 30; i++) {
            java.nio.file.Files.createDirectories(dir.resolve("s" + i));
        }
        java.nio.file.Files.createDirectories(dir.resolve(".hidden"));
        String subs = dir.toString();
        assertTrue(WarmStart.smallGrading(new String[] {"grade", "--submissions", subs, "--arenas", "maze", "lab",
            "--seeds", "1", "--jobs", "2"}), "60 runs");
        assertTrue(WarmStart.smallGrading(new String[] {"grade", "--submissions=" + subs, "--arenas=maze", "--seeds=4"}));
        assertFalse(WarmStart.smallGrading(new String[] {"grade", "--submissions", subs, "--arenas", "maze", "lab"}),
                "300 runs, 5 seeds unless given");
        assertFalse(WarmStart.smallGrading(new String[] {"grade", "--submissions", subs, "--seeds", "1"}), "no arena");
        assertFalse(WarmStart.smallGrading(new String[] {"grade", "--submissions", dir.resolve("none").toString(),
            "--arenas", "lab", "--seeds", "1"}));
        assertFalse(WarmStart.smallGrading(new String[] {"run", "--submissions", subs, "--arenas", "lab"}));
        String[] small = {"grade", "--submissions", subs, "--arenas", "lab", "--seeds", "1"};
        List<String> cmd = WarmStart.command(jvm(concat("-jar", "k.jar", small)), ARCHIVE, small);
        assertTrue(cmd.contains(WarmStart.QUICK_COMPILER), cmd.toString());
    }

    private static String[] concat(String a, String b, String[] rest) {
        List<String> all = new ArrayList<>(List.of(a, b));
        all.addAll(List.of(rest));
        return all.toArray(new String[0]);
    }

    @Test
    void noWarmJvmWhenTheCommandLineWasNotJavaJarOrChoseAnArchive() {
        for (String[] jvm : List.of(new String[] {"-Xshare:off", "-jar", "k.jar"},
                new String[] {"-XX:SharedArchiveFile=/x.jsa", "-jar", "k.jar"}, new String[] {"@opts", "-jar", "k.jar"},
                new String[] {"-cp", "k.jar", "org.kheperasim.sim.cli.Main"},
                new String[] {"--add-opens", "java.base/java.lang=ALL-UNNAMED", "-jar", "k.jar"},
                new String[] {"-jar"}, new String[] {})) {
            assertEquals(List.of(), WarmStart.command(jvm(jvm), ARCHIVE, RUN), String.join(" ", jvm));
        }
        // Arguments that are not the command's: the system's view of the command line is not what it seems.
        assertEquals(List.of(), WarmStart.command(new String[] {"-jar", "k.jar", "run"}, ARCHIVE, RUN));
    }

    /** @return these JVM arguments followed by {@link #RUN}, as the system shows a command line */
    private static String[] jvm(String... jvm) {
        List<String> all = new ArrayList<>(List.of(jvm));
        if (all.contains("-jar") && all.indexOf("-jar") + 1 < all.size() && all.size() == all.indexOf("-jar") + 2) {
            all.addAll(List.of(RUN));
        }
        return all.toArray(new String[0]);
    }
}
