package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A course controller that opens a window of its own runs trusted in the simulator's window:
 * henrihs/stupid-robot's {@code Robot} (its {@code Modeller} opens a Swing table of the map it
 * builds, and it schedules a sensor on an {@code Executors} pool, both refused untrusted), compiled
 * unchanged with its {@code config.properties} beside the classes, on its own {@code ballpickup1}
 * map, under Xvfb ({@link WsuCorpusWindowDriver}); the screenshot is
 * {@code target/wsu-corpus-henrihs-robot.png}. Needs {@code -Dkheperasim.wsuCorpus=DIR} holding the
 * clone as {@code stupid-robot} (skipped without it), and Xvfb.
 */
class WsuCorpusWindowTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void henrihsRobotRunsTrustedInTheWindowWithItsOwnWindowOpen() throws Exception {
        String corpus = System.getProperty("kheperasim.wsuCorpus");
        Assumptions.assumeTrue(corpus != null && Files.isDirectory(Path.of(corpus, "stupid-robot/src")),
                "no -Dkheperasim.wsuCorpus=DIR holding stupid-robot");
        WindowDriverRun.requireXvfb("the WSU corpus window test");
        Path src = Path.of(corpus, "stupid-robot/src");
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-nowarn", "-proc:none", "-encoding", "ISO-8859-1", "--release", "17",
                "-cp", System.getProperty("java.class.path"), "-d", classes.toString()));
        try (Stream<Path> files = Files.walk(src)) {
            files.filter(f -> f.toString().endsWith(".java"))
                    .filter(f -> !src.relativize(f).toString().replace('\\', '/').startsWith("edu/wsu/KheperaSimulator/"))
                    .forEach(f -> args.add(f.toString()));
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])),
                "the course compiles unchanged");
        Files.copy(src.resolve("config.properties"), classes.resolve("config.properties"));
        WindowDriverRun.run("the WSU corpus window test", WsuCorpusWindowDriver.class, null, 200,
                new String[] {"CORPUS WINDOW OK"}, Path.of(corpus, "stupid-robot/maps/ballpickup1").toString(),
                classes.toString(), "edu.wsu.robot.Robot", "wsu-corpus-henrihs-robot.png");
        assertTrue(Files.size(WindowDriverRun.target().resolve("wsu-corpus-henrihs-robot.png")) > 10_000, "a screenshot was saved");
    }
}
