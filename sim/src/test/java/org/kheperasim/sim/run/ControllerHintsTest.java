package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.cli.Main;

/**
 * A wrong controller name gets an answer that says what was meant and what to type, for each way
 * people get it wrong, where it used to get the same generic message every time; a source file
 * given as the classpath is named as one, where the jar reader said "zip END header not found".
 */
class ControllerHintsTest {
    @TempDir
    static Path dir;
    static Path out;
    static Path pkgOut;

    @BeforeAll
    static void compile() throws Exception {
        Path src = Files.createDirectories(dir.resolve("src"));
        Files.writeString(src.resolve("MyFirst.java"), "import org.kheperasim.api.*;\npublic class MyFirst extends Controller {\n"
                + "    @Override protected void doWork() { setSpeeds(5, 5); sleepMillis(100); }\n}\n");
        Files.writeString(src.resolve("Robot.java"), "package course.lab1;\nimport org.kheperasim.api.*;\n"
                + "public class Robot extends Controller {\n    @Override protected void doWork() { sleepMillis(100); }\n}\n");
        out = dir.resolve("out");
        pkgOut = dir.resolve("pkg-out");
        assertTrue(ControllerCompiler.compile(src.resolve("MyFirst.java"), out).success());
        assertTrue(ControllerCompiler.compile(src.resolve("Robot.java"), pkgOut).success());
    }

    private static String refusal(List<Path> classpath, String name) {
        return assertThrows(ControllerException.class, () -> new ControllerCatalog(classpath).load(name)).getMessage();
    }

    @Test
    void theCaseOfABundledOrACompiledName() {
        assertEquals("no controller named 'wallfollower': did you mean WallFollower? Names are case-sensitive: type"
                + " --controller WallFollower", refusal(List.of(), "wallfollower"));
        assertTrue(refusal(List.of(out), "myfirst").endsWith("type --controller MyFirst"), refusal(List.of(out), "myfirst"));
    }

    @Test
    void aFileNameOrAPathWhereTheClassNameBelongs() {
        String java = refusal(List.of(), "MyFirst.java");
        assertTrue(java.contains("'MyFirst.java' is a source file") && java.contains("javac -cp khepera-sim.jar -d out MyFirst.java")
                && java.contains("--classpath out --controller MyFirst"), java);
        assertTrue(refusal(List.of(out), "MyFirst.java").endsWith("type --controller MyFirst"), refusal(List.of(out), "MyFirst.java"));
        assertTrue(refusal(List.of(out), "MyFirst.class").endsWith("type --controller MyFirst"));
        String path = refusal(List.of(), "out/MyFirst.class");
        assertTrue(path.endsWith("type --classpath out --controller MyFirst (with its package, if it has one)"), path);
    }

    @Test
    void aSimpleNameWhoseClassIsInAPackageAndATypo() {
        assertEquals("no controller named 'Robot': did you mean course.lab1.Robot? A class in a package is named with its package:"
                + " type --controller course.lab1.Robot", refusal(List.of(pkgOut), "Robot"));
        assertTrue(refusal(List.of(), "WallFolower").endsWith("did you mean WallFollower? Type --controller WallFollower"));
        // Nothing near: the message says where it looked and how to compile, as before.
        assertTrue(refusal(List.of(), "Zebra").contains("it is not a bundled controller"), refusal(List.of(), "Zebra"));
    }

    @Test
    void aSourceFileAsTheClasspathIsNamedAsOneWithHowToCompileIt() throws Exception {
        Path java = dir.resolve("src").resolve("MyFirst.java");
        String m = assertThrows(ControllerException.class, () -> new ControllerCatalog(List.of(java))).getMessage();
        assertTrue(m.startsWith("classpath entry " + java + " is a Java source file") && m.contains("javac -cp khepera-sim.jar -d out")
                && m.contains("the window compiles it"), m);
        Path cls = out.resolve("MyFirst.class");
        m = assertThrows(ControllerException.class, () -> new ControllerCatalog(List.of(cls))).getMessage();
        assertTrue(m.contains("is a class file; give the folder the classes are in, --classpath " + out + " --controller MyFirst"), m);

        // On the command line: one error line, exit status 2.
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        var cl = Main.commandLine();
        cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        int code = cl.execute("run", "--arena", "lab", "--classpath", java.toString(), "--controller", "MyFirst", "--seconds", "1");
        assertEquals(ExitCodes.BAD_INPUT, code);
        String text = err.toString(StandardCharsets.UTF_8);
        assertTrue(text.startsWith("khepera-sim: error: classpath entry " + java + " is a Java source file"), text);
        assertTrue(!text.contains("zip"), text);
    }

    /** The window's command says it before opening, not at the first Start. */
    @Test
    void theGuiCommandRefusesAWrongNameWithTheHint() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        var cl = Main.commandLine();
        cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        assertEquals(ExitCodes.BAD_INPUT, cl.execute("gui", "--arena", "lab", "--controller", "wallfollower"));
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals("khepera-sim: error: no controller named 'wallfollower': did you mean WallFollower? Names are"
                + " case-sensitive: type --controller WallFollower", text.strip());
    }
}
