package org.kheperasim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * docs/quick-start.md's commands, word for word, from a folder of the student's own: the page once
 * said "save MyFirst.java anywhere" and then compiled it with a path that only works from the
 * project's folder. Here every command after the build names the jar as {@code "$KSIM"}, which step
 * 1 sets to its full path; the commands of step 3 run in a folder outside the project, with {@code
 * "$KSIM"} standing for the simulator's classes (the jar itself is packaged after the tests), and
 * end with MyFirst's result line. The window's command is checked for its words, not opened.
 */
class QuickStartTest {
    private static final Pattern SH = Pattern.compile("```sh\\n(.*?)```", Pattern.DOTALL);

    @TempDir
    Path home;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void stepThreesCommandsWorkFromAFolderOutsideTheProject() throws Exception {
        String page = Files.readString(ReadmeSnippets.root().resolve("docs/quick-start.md"));
        List<String> commands = new ArrayList<>();
        Matcher m = SH.matcher(page);
        while (m.find()) {
            m.group(1).lines().map(String::strip).filter(l -> !l.isEmpty() && !l.startsWith("#")).forEach(commands::add);
        }
        assertEquals("export KSIM=\"$PWD/sim/target/khepera-sim.jar\"", commands.get(0), "step 1 names the jar by its full path");
        assertEquals("mvn -q -DskipTests package && java -jar \"$KSIM\"", commands.get(1));
        for (String c : commands.subList(2, commands.size())) {
            assertFalse(c.contains("sim/target"), "after step 1 the jar is \"$KSIM\", which works from any folder: " + c);
        }
        String window = commands.stream().filter(c -> c.contains(" gui ")).findFirst().orElseThrow();
        assertEquals("java -jar \"$KSIM\" gui --arena lab --controller MyFirst.java", window);

        // The student's folder, anywhere but the project: MyFirst.java saved in it, as step 2 says.
        Path folder = Files.createDirectories(home.resolve("khepera-work"));
        Files.writeString(folder.resolve("MyFirst.java"), ReadmeSnippets.firstController());
        String sim = System.getProperty("java.class.path");
        String bin = Path.of(System.getProperty("java.home"), "bin").toString();
        String out = "";
        int ran = 0;
        for (String c : commands) {
            if (!c.startsWith("javac ") && !(c.startsWith("java ") && c.contains(" run "))) {
                continue;
            }
            List<String> words = new ArrayList<>(List.of(c.split(" +")));
            List<String> cmd = new ArrayList<>();
            for (int i = 0; i < words.size(); i++) {
                String w = words.get(i);
                if (w.equals("javac")) {
                    cmd.add(bin + File.separator + "javac");
                } else if (w.equals("java")) {
                    cmd.add(bin + File.separator + "java");
                } else if (w.equals("-jar") && words.get(i + 1).equals("\"$KSIM\"")) {
                    cmd.addAll(List.of("-cp", sim, "org.kheperasim.sim.cli.Main"));
                    i++;
                } else if (w.equals("\"$KSIM\"")) {
                    cmd.add(sim);
                } else {
                    cmd.add(w);
                }
            }
            Process p = new ProcessBuilder(cmd).directory(folder.toFile()).redirectErrorStream(true).start();
            out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), c);
            assertEquals(0, p.exitValue(), c + " in " + folder + ":\n" + out);
            ran++;
        }
        assertEquals(2, ran, "step 3 compiles and runs: " + commands);
        assertTrue(out.contains("MyFirst in lab: 120.0 s simulated"), out);
        assertTrue(out.contains("score "), "the result line gives the arena's score: " + out);
    }
}
