package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;

/**
 * The doors the JDK opens on a caller's behalf, tried as a clever student would (issue 28's table):
 * bean scripting, file-name constructors, XML entities, preferences, the JVM's properties and
 * environment, JMX, a class loader of one's own, other threads, thread pools. Each is refused when
 * the controller is loaded, naming the use, the student's line and the rule; nothing of it runs, so
 * nothing is written and nothing JVM-wide changes.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RefusedAtLoadTest {
    @TempDir
    static Path dir;
    static Path classes;
    static Path target;

    /** Name, the body of doWork() (its last statement is the one refused), and what the refusal names. */
    private static final String[][] DOORS = {
        {"XmlDecoderBot", "String xml = \"<java><object class='java.lang.ProcessBuilder'><array class='java.lang.String'"
            + " length='2'><void index='0'><string>touch</string></void><void index='1'><string>\" + TARGET"
            + " + \"</string></void></array><void method='start'/></object></java>\";\n"
            + "new java.beans.XMLDecoder(new java.io.ByteArrayInputStream(xml.getBytes())).readObject();",
            "uses java.beans.XMLDecoder: bean scripting"},
        {"ExpressionBot", "new java.beans.Expression(Runtime.getRuntime(), \"exec\", new Object[] {new String[] {\"touch\","
            + " TARGET}}).getValue();", "uses java.beans.Expression: bean scripting"},
        {"PrintWriterBot", "new java.io.PrintWriter(TARGET).close();", "uses new java.io.PrintWriter(String): a PrintWriter on a"
            + " file name"},
        {"PrintStreamBot", "new java.io.PrintStream(TARGET).close();", "uses new java.io.PrintStream(String): a PrintStream of"
            + " one's own would write a file"},
        {"FormatterBot", "new java.util.Formatter(TARGET).close();", "uses new java.util.Formatter(String): a Formatter on a"
            + " file name"},
        {"TransformBot", "String xml = \"<!DOCTYPE x [<!ENTITY e SYSTEM 'file:///etc/passwd'>]><x>&e;</x>\";\n"
            + "javax.xml.transform.TransformerFactory.newInstance().newTransformer().transform(new javax.xml.transform.stream"
            + ".StreamSource(new java.io.StringReader(xml)), new javax.xml.transform.stream.StreamResult(new java.io"
            + ".StringWriter()));", "uses javax.xml.transform.TransformerFactory.newInstance(): XML parsers and transforms"
            + " read external entities"},
        {"PreferencesBot", "java.util.prefs.Preferences.userRoot().node(\"kheperasim-refused\").put(\"k\", \"v\");",
            "uses java.util.prefs.Preferences.userRoot(): preferences are files that outlive the run"},
        {"PropertiesBot", "System.getProperties().setProperty(\"java.io.tmpdir\", TARGET);",
            "uses java.lang.System.getProperties(): controllers may not read or change the JVM's settings"},
        {"EnvironmentBot", "print(String.valueOf(System.getenv()));",
            "uses java.lang.System.getenv(): controllers may not read or change the JVM's settings"},
        {"ManagementBot", "print(String.valueOf(java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments()));",
            "uses java.lang.management.ManagementFactory.getRuntimeMXBean(): management (JMX)"},
        {"HeapDumpBot", "java.lang.management.ManagementFactory.getPlatformMBeanServer().invoke(new javax.management"
            + ".ObjectName(\"com.sun.management:type=HotSpotDiagnostic\"), \"dumpHeap\", new Object[] {TARGET, true},"
            + " new String[] {\"java.lang.String\", \"boolean\"});",
            "uses java.lang.management.ManagementFactory.getPlatformMBeanServer(): management (JMX)"},
        {"MLetBot", "new javax.management.loading.MLet().addURL(\"file:///tmp/\");",
            "uses javax.management.loading.MLet: JMX: MBeans dump the heap, and MLet loads classes from anywhere"},
        {"SuspendBot", "for (Thread t : Thread.getAllStackTraces().keySet()) { if (t != Thread.currentThread()) t.suspend(); }",
            "uses java.lang.Thread.getAllStackTraces(): a controller may reach only its own threads"},
        {"GroupStopBot", "ThreadGroup g = Thread.currentThread().getThreadGroup(); while (g.getParent() != null) g = g.getParent();"
            + " g.stop();", "uses java.lang.Thread.getThreadGroup(): a controller may reach only its own threads"},
        {"PoolBot", "java.util.concurrent.Executors.newFixedThreadPool(2).submit(() -> { while (true) { } });",
            "uses java.util.concurrent.Executors.newFixedThreadPool(int): thread pools run tasks on threads the JDK starts"},
    };

    /** Each controller's name and the line of the use its refusal must name. */
    private static final Map<String, Integer> LINES = new java.util.HashMap<>();

    @BeforeAll
    static void compile() throws IOException {
        classes = Files.createDirectories(dir.resolve("classes"));
        target = dir.resolve("written.txt");
        List<String> files = new ArrayList<>();
        for (String[] d : DOORS) {
            String head = "import org.kheperasim.api.*;\n\npublic class " + d[0] + " extends Controller {\n"
                    + "    static final String TARGET = \"" + target.toString().replace("\\", "\\\\") + "\";\n\n"
                    + "    @Override\n    protected void doWork() {\n        try {\n";
            String body = "            " + d[1].replace("\n", "\n            ") + "\n";
            String text = head + body + "        } catch (Exception e) {\n            print(e.toString());\n        }\n"
                    + "        sleepMillis(100);\n    }\n}\n";
            LINES.put(d[0], (int) (head + body).lines().count());
            files.add(write(d[0], text));
        }
        files.add(write("LoaderBot", """
                import org.kheperasim.api.*;

                public class LoaderBot extends Controller {
                    static class Definer extends java.security.SecureClassLoader {
                        Class<?> define(byte[] b) {
                            return defineClass(null, b, 0, b.length);
                        }
                    }

                    @Override
                    protected void doWork() {
                        new Definer();
                        sleepMillis(100);
                    }
                }
                """));
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "-g", "--release", "17", "-proc:none", "-nowarn"));
        args.addAll(files);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])),
                "the controllers compile");
    }

    private static String write(String name, String text) throws IOException {
        Path f = dir.resolve(name + ".java");
        Files.writeString(f, text);
        return f.toString();
    }

    private static ControllerException refusal(String controller) {
        return assertThrows(ControllerException.class, () -> Simulation.builder().arena("lab").classpath(List.of(classes))
                .controller(controller).seed(1).seconds(1).run(), controller + " is refused");
    }

    @Test
    void eachDoorIsRefusedAtLoadNamingTheUseTheLineAndTheRuleAndNothingHappens() throws Exception {
        Properties before = (Properties) System.getProperties().clone();
        for (String[] d : DOORS) {
            String message = refusal(d[0]).getMessage();
            assertTrue(message.startsWith("controller " + d[0] + " was refused: "), message);
            assertTrue(message.contains(d[0] + ".java:" + LINES.get(d[0]) + ": " + d[2]),
                    d[0] + " names its line " + LINES.get(d[0]) + " and the rule '" + d[2] + "': " + message);
        }
        String loader = refusal("LoaderBot").getMessage();
        assertTrue(loader.contains("LoaderBot.java:4: extends java.security.SecureClassLoader: controllers may not define or load"
                + " classes themselves"), "a class of its own that extends SecureClassLoader: " + loader);

        assertFalse(Files.exists(target), "nothing was written");
        assertFalse(Files.exists(Path.of(System.getProperty("user.home"), ".java/.userPrefs/kheperasim-refused")),
                "no preferences were stored");
        assertEquals(before, System.getProperties(), "no system property changed");
    }

    /**
     * A class of the Java platform's packages that this JVM lacks (as Java 23 and later lack
     * javax.management.loading.MLet) is refused by the allowlist like any other, not let through as
     * a class of the controller's own that happens to be missing: the refusal is the same on every JDK.
     */
    @Test
    void aPlatformClassThisJvmLacksIsRefusedAsOnAJdkThatHasIt() throws Exception {
        Path src = Files.createDirectories(dir.resolve("gone-src"));
        Path out = Files.createDirectories(dir.resolve("gone-classes"));
        Path door = Files.createDirectories(src.resolve("javax/gone")).resolve("Door.java");
        Files.writeString(door, "package javax.gone;\npublic class Door {\n    public static void open() {\n    }\n}\n");
        Path bot = src.resolve("GoneBot.java");
        Files.writeString(bot, """
                import org.kheperasim.api.*;

                public class GoneBot extends Controller {
                    @Override
                    protected void doWork() {
                        javax.gone.Door.open();
                        sleepMillis(100);
                    }
                }
                """);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", out.toString(), "-g", "--release", "17", "-proc:none", "-nowarn", door.toString(), bot.toString()));
        Files.delete(out.resolve("javax/gone/Door.class")); // at load, no such class exists anywhere
        String message = assertThrows(ControllerException.class, () -> Simulation.builder().arena("lab")
                .classpath(List.of(out)).controller("GoneBot").seed(1).seconds(1).run()).getMessage();
        assertTrue(message.contains("GoneBot.java:6: uses javax.gone.Door.open(): "), message);
    }

    /** From the command line: exit status 2 (a controller that cannot be used at all), one error line, nothing run. */
    @Test
    void theCommandLineRefusesItWithStatus2AndOneLine() throws Exception {
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "run", "--arena", "lab", "--classpath",
                classes.toString(), "--controller", "XmlDecoderBot", "--seconds", "5").start();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        p.getInputStream().transferTo(new ByteArrayOutputStream());
        p.getErrorStream().transferTo(err);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "it ends");
        String text = err.toString(StandardCharsets.UTF_8).strip();
        assertEquals(2, p.exitValue(), text);
        assertTrue(text.startsWith("khepera-sim: error: controller XmlDecoderBot was refused: ") && !text.contains("\n"),
                "one line: " + text);
        assertTrue(text.contains("XmlDecoderBot.java:" + LINES.get("XmlDecoderBot") + ": uses java.beans.XMLDecoder"), text);
        assertFalse(Files.exists(target), "no shell ran");
    }
}
