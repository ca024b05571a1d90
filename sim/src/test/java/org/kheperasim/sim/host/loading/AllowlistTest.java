package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Executable;
import java.lang.reflect.Member;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kheperasim.sim.host.loading.AllowlistEntry.Kind;
import org.kheperasim.sim.host.loading.AllowlistEntry.MemberItem;
import org.kheperasim.sim.host.loading.AllowlistEntry.PatternKind;

/**
 * The allowlist decides on members, not only classes, and on the member the JVM would reach, not the
 * class a call names: each case compiles a small controller and asks the loader's own check.
 */
class AllowlistTest {
    /** Members the list names for a newer Java than this build's 17. */
    private static final Set<String> NEWER_THAN_17 = Set.of("java.lang.runtime.SwitchBootstraps.enumSwitch");

    @TempDir
    Path dir;

    private int compiled;

    /** @return the refusal of a class compiled from {@code source} (with its helpers), or null when it loads */
    private String refusal(String className, Map<String, String> sources) throws IOException {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("c" + compiled++)), sources);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader())) {
            loader.loadClass(className);
            return null;
        } catch (ControllerPolicyError e) {
            return e.getMessage();
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);
        }
    }

    /** @return the refusal of a class {@code Bot} whose method {@code use} holds {@code statement} on line 5 */
    private String refusalOf(String statement) throws IOException {
        return refusal("Bot", Map.of("Bot", "import java.util.*;\n\npublic class Bot {\n    void use() throws Exception {\n        "
                + statement + ";\n    }\n}\n"));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', value = {
        "System.out.println(\"x\")",
        "System.err.printf(\"%d%n\", 1)",
        "System.out.flush()",
        "new Thread(() -> { }).start()",
        "Thread.currentThread().join(5)",
        "Thread.sleep(1)",
        "System.currentTimeMillis()",
        "System.nanoTime()",
        "new ArrayList<String>().forEach(s -> { })",
        "new ArrayList<String>().stream().map(String::length).toList()",
        "new TreeMap<String, Integer>().merge(\"a\", 1, Integer::sum)",
        "Comparator.<String>naturalOrder().reversed().thenComparing(String::length)",
        "new StringBuilder().append(1).length()",
        "String.format(java.util.Locale.ROOT, \"%.1f\", Math.PI)",
        "new Random(1).nextInt(0, 5)",
        "java.time.LocalDateTime.now().plusSeconds(3)",
        "new Date().getTime()",
        "new java.util.GregorianCalendar(java.util.TimeZone.getTimeZone(\"UTC\")).getTimeInMillis()",
        "new java.util.Properties().load(new java.io.StringReader(\"a=b\"))",
        "new Scanner(\"1 2\").nextInt()",
    })
    void theseAreAllowed(String statement) throws IOException {
        assertNull(refusalOf(statement));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', value = {
        "new java.io.PrintStream(\"out.txt\")| new java.io.PrintStream(String): a PrintStream of one's own would write a file",
        "System.out.close()| java.io.PrintStream.close(): closing or writing bytes",
        "((AutoCloseable) System.out).close()| java.lang.AutoCloseable.close(): closing through the interface",
        "Thread.currentThread().stop()| java.lang.Thread.stop(): a controller may reach only its own threads",
        "Thread.currentThread().suspend()| java.lang.Thread.suspend(): a controller may reach only its own threads",
        "Thread.getAllStackTraces()| java.lang.Thread.getAllStackTraces(): a controller may reach only its own threads",
        "Thread.currentThread().getThreadGroup()| java.lang.Thread.getThreadGroup(): a controller may reach",
        "new Thread(new ThreadGroup(\"g\"), () -> { })| java.lang.ThreadGroup: a controller may reach only its own threads",
        "System.getProperties()| java.lang.System.getProperties(): controllers may not read or change the JVM's settings",
        "System.getenv()| java.lang.System.getenv(): controllers may not read or change the JVM's settings",
        "System.getProperty(\"user.home\")| java.lang.System.getProperty(String): controllers may not read",
        "System.in.read()| java.lang.System.in: controllers may not read or change the JVM's settings",
        "Integer.getInteger(\"x\")| java.lang.Integer.getInteger(String): it reads a system property",
        "Locale.setDefault(Locale.ROOT)| java.util.Locale.setDefault(Locale): it would change the locale of the whole JVM",
        "new Formatter(\"out.txt\")| new java.util.Formatter(String): a Formatter on a file name",
        "new Scanner(new java.io.File(\"x\"))| java.io.File: controllers may not touch files",
        "java.util.Arrays.parallelSort(new int[3])| java.util.Arrays.parallelSort(int[]): it runs on the JDK's common pool",
        "Class.forName(\"java.lang.Runtime\")| java.lang.Class.forName(String): controllers may not use reflection",
        "getClass().getDeclaredMethods()| java.lang.Class.getDeclaredMethods(): controllers may not use reflection",
        "Runtime.getRuntime().exec(\"true\")| java.lang.Runtime.exec(String): controllers may not start processes",
        "java.lang.invoke.LambdaMetafactory.metafactory(null, null, null, null, null, null)"
            + "| java.lang.invoke.LambdaMetafactory.metafactory(MethodHandles$Lookup, String, MethodType, MethodType,"
            + " MethodHandle, MethodType): controllers may not use method handles",
        "java.util.logging.Logger.getGlobal()| java.util.logging.Logger.getGlobal(): loggers, handlers and the log manager",
        "new java.awt.Frame().setVisible(true)| java.awt.Frame: a controller that opens a window of its own runs only"
            + " trusted: in the window, tick Controller > Trust this controller; headless, run --trusted",
    })
    void theseAreRefusedNamingTheMemberTheLineAndTheRule(String statement, String expected) throws IOException {
        String message = refusalOf(statement);

        assertTrue(message != null && message.contains("Bot.java:5: uses " + expected.strip()), statement + ": " + message);
        assertTrue(message.endsWith("(" + ControllerPolicy.DOCS + ")"), message);
    }

    @Test
    void aMemberIsJudgedWhereTheJvmFindsItNotWhereTheCallNamesIt() throws IOException {
        // Inherited from an allowed JDK class, through a class of the controller's own.
        assertNull(refusal("Names", Map.of("Names", """
                import java.util.*;
                public class Names extends ArrayList<String> {
                    int use() { add("a"); removeIf(String::isEmpty); return stream().mapToInt(String::length).sum() + size(); }
                }
                """)));
        // An interface's default method, through an interface of its own.
        assertNull(refusal("Shorter", Map.of("Shorter", """
                import java.util.Comparator;
                public interface Shorter extends Comparator<String> {
                    default int compare(String a, String b) { return a.length() - b.length(); }
                    static Comparator<String> longestFirst() { Shorter s = new Shorter() { }; return s.reversed(); }
                }
                """)));
        // A forbidden JDK method, called unqualified in a Thread subclass of its own.
        String stopper = refusal("Stopper", Map.of("Stopper", """
                public class Stopper extends Thread {
                    @Override public void run() {
                        stop();
                    }
                }
                """));
        assertTrue(stopper != null && stopper.contains("Stopper.java:3: uses java.lang.Thread.stop() (called through Stopper):"),
                stopper);
    }

    @Test
    void aClassThatExtendsOrImplementsATypeNotOnTheListIsRefused() throws IOException {
        String loader = refusal("Definer", Map.of("Definer", """
                public class Definer extends java.security.SecureClassLoader {
                    Class<?> make(byte[] b) { return defineClass("X", b, 0, b.length, (java.security.CodeSource) null); }
                }
                """));
        assertTrue(loader != null && loader.contains("Definer.java:1: extends java.security.SecureClassLoader: controllers may not"
                + " define or load classes themselves"), loader);
        String listener = refusal("Clicker", Map.of("Clicker", """
                public class Clicker implements java.awt.event.ActionListener {
                    public void actionPerformed(java.awt.event.ActionEvent e) { }
                }
                """));
        assertTrue(listener != null && listener.contains("Clicker.java:1: implements java.awt.event.ActionListener: a controller that"
                + " opens a window of its own runs only trusted: in the window, tick Controller > Trust this controller"), listener);
    }

    @Test
    void aHelperClassThatBreaksARuleRefusesTheControllerWhenItLoads() throws IOException {
        String message = refusal("Robot", Map.of("Robot", """
                public class Robot extends Thread {
                    @Override public void run() { if (System.nanoTime() < 0) Helper.spy(); }
                }
                """, "Helper", """
                public class Helper {
                    static void spy() {
                        System.getenv("HOME");
                    }
                }
                """));
        assertTrue(message != null && message.contains("Helper.java:3: uses java.lang.System.getenv(String)"), message);
    }

    @Test
    void aFinalizerIsRefusedAtItsLine() throws IOException {
        String message = refusal("Tidy", Map.of("Tidy", """
                public class Tidy {
                    @Override protected void finalize() {
                        System.out.println("gone");
                    }
                }
                """));
        assertTrue(message != null && message.contains("Tidy.java:3: declares finalize(): a finalizer runs on the JVM's finalizer"
                + " thread"), message);
    }

    @Test
    void trustedCodeIsNotChecked() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("trusted")), Map.of("Env",
                "public class Env { public static String home() { return System.getenv(\"HOME\"); } }"));
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader(), false)) {
            assertEquals(System.getenv("HOME"), loader.loadClass("Env").getMethod("home").invoke(null));
        }
    }

    @Test
    void theMostSpecificItemDecides() {
        Allowlist list = new Allowlist(AllowlistParser.parse("test", """
                == Test
                a.B  * -x -y* y(int) new(java.lang.String) -new  -- a test
                a.*  z x  -- the package
                a.C < a.B  w  -- only if it extends a.B
                """));
        Map<String, Boolean> asked = new java.util.LinkedHashMap<>();
        asked.put("v", list.allowsMember("a.B", "v", List.of(), false, (t, s) -> false));
        asked.put("x", list.allowsMember("a.B", "x", List.of(), false, (t, s) -> false));
        asked.put("yes()", list.allowsMember("a.B", "yes", List.of(), false, (t, s) -> false));
        asked.put("y(int)", list.allowsMember("a.B", "y", List.of("int"), false, (t, s) -> false));
        asked.put("y(long)", list.allowsMember("a.B", "y", List.of("long"), false, (t, s) -> false));
        asked.put("new(String)", list.allowsMember("a.B", "<init>", List.of("java.lang.String"), false, (t, s) -> false));
        asked.put("new()", list.allowsMember("a.B", "<init>", List.of(), false, (t, s) -> false));
        asked.put("B.z", list.allowsMember("a.B", "z", null, false, (t, s) -> false));
        asked.put("D.z", list.allowsMember("a.D", "z", null, false, (t, s) -> false));
        asked.put("C.w", list.allowsMember("a.C", "w", null, false, (t, s) -> true));
        Allowlist again = new Allowlist(list.entries()); // answers are remembered per list: a hierarchy is stable
        asked.put("C.w unrelated", again.allowsMember("a.C", "w", null, false, (t, s) -> false));
        asked.put("B as bootstrap", list.allowsMember("a.B", "v", List.of(), true, (t, s) -> false));
        assertEquals(new java.util.TreeMap<>(Map.ofEntries(Map.entry("v", true), Map.entry("x", false), Map.entry("yes()", false),
                Map.entry("y(int)", true), Map.entry("y(long)", false), Map.entry("new(String)", true), Map.entry("new()", false),
                Map.entry("B.z", true), Map.entry("D.z", true), Map.entry("C.w", true), Map.entry("C.w unrelated", false),
                Map.entry("B as bootstrap", false))), new java.util.TreeMap<>(asked));
    }

    @Test
    void aMalformedEntryNamesItsLine() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> AllowlistParser.parse("list.txt", "== G\njava.lang.String *\n"));
        assertEquals("list.txt:2: no ' -- ' before the entry's reason: every entry says why", e.getMessage());
    }

    /** A typo in the list would allow nothing, or something else: every class and member it names exists. */
    @Test
    void theListNamesOnlyClassesAndMembersThatExist() {
        List<String> missing = new ArrayList<>();
        int members = 0;
        for (AllowlistEntry e : Allowlist.bundled().entries()) {
            if (e.group().kind() == Kind.REFUSED || e.classes().kind() != PatternKind.EXACT) {
                continue;
            }
            Class<?> type;
            try {
                type = Class.forName(e.classes().value(), false, getClass().getClassLoader());
            } catch (ClassNotFoundException ex) {
                missing.add(e.classes().value() + " (line " + e.line() + ")");
                continue;
            }
            for (MemberItem item : e.members()) {
                if (item.name().equals("*") || item.prefix()) {
                    continue;
                }
                members++;
                String name = e.classes().value() + "." + item.name();
                if (!declares(type, item) && !NEWER_THAN_17.contains(name)) {
                    missing.add(name + (item.parameters() == null ? "" : item.parameters().toString()) + " (line " + e.line() + ")");
                }
            }
        }
        assertEquals(List.of(), missing);
        assertTrue(members > 100, "the list names members one by one: " + members);
    }

    private static boolean declares(Class<?> type, MemberItem item) {
        Stream<Member> declared = Stream.of(type.getDeclaredMethods(), type.getDeclaredConstructors(), type.getDeclaredFields())
                .flatMap(Arrays::stream);
        return declared.anyMatch(m -> (m instanceof java.lang.reflect.Constructor<?> ? "<init>" : m.getName()).equals(item.name())
                && (item.parameters() == null || m instanceof Executable x && Arrays.stream(x.getParameterTypes())
                        .map(Class::getTypeName).map(n -> n.replace('$', '.'))
                        .toList().equals(item.parameters().stream().map(n -> n.replace('$', '.')).toList())));
    }

    @Test
    void everyAllowedGroupSaysWhyForEachEntry() {
        for (AllowlistEntry e : Allowlist.bundled().entries()) {
            assertFalse(e.reason().isBlank(), "line " + e.line());
        }
    }
}
