package org.kheperasim.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.ControllerCompiler;
import org.kheperasim.sim.sandbox.BoxProbe;
import org.kheperasim.testfixtures.Cli;

/**
 * What a student's own machine brings, as far as this one can show it: files saved with Windows's line
 * ends (CRLF), folders whose names hold spaces and letters beyond ASCII (a home folder "Élève dossier",
 * OneDrive's "Mes documents"), and no bubblewrap. A CRLF arena runs exactly as the same arena with LF
 * line ends; a CRLF controller compiles, in the window's compiler and with javac, with its errors on
 * their own lines; classes, arenas and traces in such folders are found and written; without
 * bubblewrap {@code grade} and {@code run --sandbox} refuse with the way on, and {@code run} runs.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class StudentMachineTest {
    @TempDir
    Path home;

    private static String crlf(String text) {
        return text.replace("\r\n", "\n").replace("\n", "\r\n");
    }

    /** The simulator's command line in a JVM of its own, started in {@code folder}, with extra JVM options. */
    private static Cli.Printed child(Path folder, List<String> jvm, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(jvm);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(folder.toFile()).start();
        p.getOutputStream().close();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Thread drain = new Thread(() -> {
            try {
                p.getErrorStream().transferTo(err);
            } catch (java.io.IOException e) {
                // the child has gone
            }
        });
        drain.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), String.join(" ", args));
        drain.join();
        return new Cli.Printed(p.exitValue(), out, err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void crlfFilesInFoldersWithSpacesAndAccentsRunAsTheirLfTwins() throws Exception {
        Path folder = Files.createDirectories(home.resolve("Élève dossier").resolve("Mes contrôleurs"));
        Path source = folder.resolve("MyFirst.java");
        Files.writeString(source, crlf(ReadmeSnippets.firstController()));
        Path arena = folder.resolve("labyrinthe é.arena");
        String maze = new String(ArenaFormat.class.getResourceAsStream("/arenas/maze.arena").readAllBytes(), StandardCharsets.UTF_8);
        Files.writeString(arena, crlf(maze));
        assertTrue(Files.readString(arena).contains("\r\n"));

        // The window's compiler (File > Open controller) on the CRLF source, into a folder with spaces and accents.
        Path classes = folder.resolve("classes é");
        ControllerCompiler.Result compiled = ControllerCompiler.compile(source, classes);
        assertTrue(compiled.success(), compiled.report("MyFirst.java"));
        assertEquals("MyFirst", compiled.className());

        Path crlfTrace = folder.resolve("traces é").resolve("run 1.trace");
        Cli.Printed crlfRun = Cli.main("run", "--arena", arena.toString(), "--classpath", classes.toString(), "--controller", "MyFirst",
                "--seconds", "20", "--seed", "1", "--trace", crlfTrace.toString());
        assertEquals(0, crlfRun.code(), crlfRun.out() + crlfRun.err());
        Path lfTrace = home.resolve("lf.trace");
        Cli.Printed lfRun = Cli.main("run", "--arena", "maze", "--classpath", classes.toString(), "--controller", "MyFirst",
                "--seconds", "20", "--seed", "1", "--trace", lfTrace.toString());
        assertEquals(0, lfRun.code(), lfRun.out() + lfRun.err());
        assertArrayEquals(Files.readAllBytes(lfTrace), Files.readAllBytes(crlfTrace),
                "the CRLF arena in an accented folder runs byte for byte as the bundled one");
        Cli.Printed verify = Cli.main("verify", "--classpath", classes.toString(), crlfTrace.toString());
        assertEquals(0, verify.code(), verify.out() + verify.err());
        assertTrue(verify.out().startsWith("identical"), verify.out());
    }

    /**
     * {@code verify} and {@code bench} split {@code --classpath} at the system's path separator, as {@code run} and
     * javac do: they split at ':' and ';' both, which cut a Windows path ({@code C:\\Users\\...}) at its drive
     * letter. The same mistake seen from here: a folder whose name holds a ';' (the other system's separator).
     */
    @Test
    void verifySplitsItsClasspathAtThisSystemsSeparatorOnly() throws Exception {
        String other = File.pathSeparatorChar == ':' ? ";" : ":";
        org.junit.jupiter.api.Assumptions.assumeTrue(other.equals(";"), "a folder name may hold ';' on Unix only");
        Path folder = Files.createDirectories(home.resolve("dossier" + other + " é"));
        Path source = folder.resolve("MyFirst.java");
        Files.writeString(source, ReadmeSnippets.firstController());
        Path classes = folder.resolve("classes");
        assertTrue(ControllerCompiler.compile(source, classes).success());
        Path trace = folder.resolve("run.trace");
        Cli.Printed run = Cli.main("run", "--arena", "lab", "--classpath", classes.toString(), "--controller", "MyFirst", "--seconds", "5",
                "--seed", "1", "--trace", trace.toString());
        assertEquals(0, run.code(), run.out() + run.err());
        Cli.Printed verify = Cli.main("verify", "--classpath", classes + File.pathSeparator + home, trace.toString());
        assertEquals(0, verify.code(), verify.out() + verify.err());
        assertTrue(verify.out().startsWith("identical"), verify.out());
    }

    @Test
    void aCrlfControllersErrorsAreOnTheirOwnLines() throws Exception {
        Path folder = Files.createDirectories(home.resolve("Mes documents é"));
        Path source = folder.resolve("Broken.java");
        Files.writeString(source, crlf("import org.kheperasim.api.*;\n\npublic class Broken extends Controller {\n"
                + "    @Override\n    protected void doWork() {\n        setSpeeds(5, 5)\n    }\n}\n"));
        ControllerCompiler.Result r = ControllerCompiler.compile(source, folder.resolve("classes"));
        assertTrue(!r.success() && r.problems().get(0).line() == 6, "the missing ';' is on line 6: " + r.report("Broken.java"));
    }

    @Test
    void withoutBubblewrapGradeAndRunSandboxRefuseWithTheWayOnAndRunRuns() throws Exception {
        Path none = Files.createDirectories(home.resolve("no tools here"));
        List<String> noBox = List.of("-D" + BoxProbe.PATH_PROPERTY + "=" + none);
        Path subs = Files.createDirectories(home.resolve("élèves").resolve("alice"));
        Files.writeString(subs.resolve("MyFirst.java"), ReadmeSnippets.firstController());
        Cli.Printed grade = child(home, noBox, "grade", "--submissions", subs.getParent().toString(), "--arenas", "lab",
                "--seeds", "1", "--seconds", "5", "--out", home.resolve("report").toString());
        assertEquals(2, grade.code(), grade.out() + grade.err());
        String line = grade.err().strip();
        assertEquals(1, line.lines().count(), "one line: " + line);
        assertTrue(line.startsWith("khepera-sim: error: grade runs code that is not your own in a bubblewrap sandbox, but"
                + " bubblewrap (bwrap) is not installed"), line);
        assertTrue(line.contains("apt-get install bubblewrap") && line.contains("give --no-sandbox"), line);

        Cli.Printed sandboxed = child(home, noBox, "run", "--sandbox", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "5");
        assertEquals(2, sandboxed.code(), sandboxed.out() + sandboxed.err());
        assertTrue(sandboxed.err().contains("bubblewrap (bwrap) is not installed") && sandboxed.err().contains("leave --sandbox out"),
                sandboxed.err());

        Cli.Printed run = child(home, noBox, "run", "--arena", "lab", "--controller", "Braitenberg", "--seconds", "5", "--seed", "1");
        assertEquals(0, run.code(), run.out() + run.err());
        assertTrue(run.out().contains("Braitenberg in lab: 5.0 s simulated"), run.out());
    }
}
