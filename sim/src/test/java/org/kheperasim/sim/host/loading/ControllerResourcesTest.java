package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A contained controller reads the resources of its own classpath entry (its folder or its jar),
 * read-only, every way course code asks for them, and nothing else: not the simulator's jar or
 * classpath, not a file beside the entry, whichever class or loader it asks.
 */
class ControllerResourcesTest {
    /** Reads in each way course code does; each answer is the text read, or "none". */
    private static final String READER = """
            package bot;
            import java.io.*;
            import java.net.URL;
            import java.nio.charset.StandardCharsets;
            import java.util.*;
            public class Reader implements java.util.function.Supplier<String> {
                static String text(InputStream in) throws IOException {
                    if (in == null) {
                        return "none";
                    }
                    try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                        return r.readLine();
                    }
                }
                static String url(URL url) throws IOException {
                    return url == null ? "none" : text(url.openStream());
                }
                public String get() {
                    try {
                        Properties p = new Properties();
                        p.load(getClass().getResourceAsStream("config.properties"));
                        return String.join(",", p.getProperty("speed"),
                                text(getClass().getResourceAsStream("/top.txt")),
                                text(getClass().getClassLoader().getResourceAsStream("bot/config.properties")),
                                text(Thread.currentThread().getContextClassLoader().getResourceAsStream("top.txt")),
                                url(getClass().getResource("config.properties")),
                                url(getClass().getClassLoader().getResource("top.txt")),
                                new Scanner(Reader.class.getResourceAsStream("/top.txt")).nextLine(),
                                text(String.class.getResourceAsStream("/top.txt")),
                                text(getClass().getResourceAsStream("/org/kheperasim/sim/host/loading/controller-allowlist.txt")),
                                text(String.class.getResourceAsStream("/java/lang/Object.class")),
                                text(getClass().getResourceAsStream("../../outside.txt")),
                                text(getClass().getResourceAsStream("/org/junit/jupiter/api/Test.class")),
                                url(Thread.currentThread().getContextClassLoader().getResource("META-INF/MANIFEST.MF")));
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                }
            }
            """;

    /** Own resources read, in each way; the simulator's resources and a file outside the entry not. */
    private static final String EXPECTED = "7,top,speed=7,top,speed=7,top,top,top,none,none,none,none,none";

    @TempDir
    Path dir;

    @Test
    void aControllerInAFolderReadsItsOwnResourcesOnly() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("classes")), Map.of("bot.Reader", READER));
        Files.writeString(classes.resolve("bot/config.properties"), "speed=7\n");
        Files.writeString(classes.resolve("top.txt"), "top\n");
        Files.writeString(dir.resolve("outside.txt"), "outside\n");

        assertEquals(EXPECTED, read(classes));
    }

    @Test
    void aControllerInAJarReadsItsOwnResourcesOnly() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("classes")), Map.of("bot.Reader", READER));
        Files.writeString(classes.resolve("bot/config.properties"), "speed=7\n");
        Files.writeString(classes.resolve("top.txt"), "top\n");
        Path jar = dir.resolve("bot.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar)); Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                out.putNextEntry(new JarEntry(classes.relativize(f).toString().replace('\\', '/')));
                Files.copy(f, (OutputStream) out);
            }
        }

        assertEquals(EXPECTED, read(jar));
    }

    /** Reads each named resource every way a controller can; each answer is its first line, or "none". */
    private static final String LINK_READER = """
            package bot;
            import java.io.*;
            import java.net.URL;
            import java.nio.charset.StandardCharsets;
            public class LinkReader implements java.util.function.Function<String, String> {
                static String text(InputStream in) throws IOException {
                    if (in == null) {
                        return "none";
                    }
                    try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                        String line = r.readLine();
                        return line == null ? "empty" : line.replace('\0', ' ').trim();
                    }
                }
                static String url(URL url) throws IOException {
                    return url == null ? "none" : text(url.openStream());
                }
                public String apply(String name) {
                    try {
                        return String.join("|", text(getClass().getResourceAsStream("/" + name)),
                                text(getClass().getClassLoader().getResourceAsStream(name)),
                                text(Thread.currentThread().getContextClassLoader().getResourceAsStream(name)),
                                url(getClass().getResource("/" + name)),
                                url(getClass().getClassLoader().getResource(name)));
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                }
            }
            """;

    /** Links a student could leave beside their classes: out of the entry (refused) and within it (a file of its own). */
    private Path linkedEntry() throws IOException {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("classes")), Map.of("bot.LinkReader", LINK_READER));
        Path other = Files.createDirectories(dir.resolve("other-student"));
        Files.writeString(other.resolve("Secret.java"), "another student's source\n");
        Files.writeString(dir.resolve("beside.txt"), "beside the entry\n");
        Files.writeString(classes.resolve("real.txt"), "my own\n");
        try {
            Files.createSymbolicLink(classes.resolve("passwd.txt"), Path.of("/etc/passwd"));
        } catch (UnsupportedOperationException | IOException e) {
            org.junit.jupiter.api.Assumptions.abort("no symbolic links on this file system: " + e);
        }
        Files.createSymbolicLink(classes.resolve("cmdline.txt"), Path.of("/proc/1/cmdline"));
        Files.createSymbolicLink(classes.resolve("other"), Path.of("../other-student"));
        Files.createSymbolicLink(classes.resolve("beside.txt"), Path.of("../beside.txt"));
        Files.createDirectories(classes.resolve("sub"));
        Files.createSymbolicLink(classes.resolve("sub/up.txt"), Path.of("../../beside.txt"));
        Files.createSymbolicLink(classes.resolve("mine.txt"), Path.of("real.txt"));
        Files.createSymbolicLink(classes.resolve("sub/mine.txt"), Path.of("../real.txt"));
        return classes;
    }

    /** Issue 35, item 9: a link out of the entry is no resource of the controller's, whichever way it asks. */
    @Test
    void aLinkOutOfTheFolderIsNotFoundAndALinkWithinItIs() throws Exception {
        Path classes = linkedEntry();
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader())) {
            @SuppressWarnings("unchecked")
            java.util.function.Function<String, String> reader = (java.util.function.Function<String, String>)
                    loader.loadClass("bot.LinkReader").getConstructor().newInstance();
            String none = "none|none|none|none|none";
            for (String out : List.of("passwd.txt", "cmdline.txt", "other/Secret.java", "beside.txt", "sub/up.txt",
                    "sub/../other/Secret.java")) {
                assertEquals(none, reader.apply(out), out);
                assertEquals(null, loader.getResource(out), "the simulator's own look-up: " + out);
                assertEquals(null, loader.ownResource(out), out);
            }
            String mine = "my own|my own|my own|my own|my own";
            assertEquals(mine, reader.apply("real.txt"));
            assertEquals(mine, reader.apply("mine.txt"), "a link to a file of its own is its own");
            assertEquals(mine, reader.apply("sub/mine.txt"));
        }
    }

    /** The same in a run (what {@code run}, {@code evaluate}, {@code serve}, the window and the testing module start). */
    @Test
    void aRunningControllerDoesNotReadThroughALinkOut() throws Exception {
        Path classes = linkedEntry();
        JavaSources.compile(classes, Map.of("Peeker", """
                import org.kheperasim.api.*;
                public class Peeker extends Controller {
                    @Override
                    protected void doWork() {
                        print("peek " + new bot.LinkReader().apply("passwd.txt") + " " + new bot.LinkReader().apply("mine.txt"));
                        sleepMillis(10_000);
                    }
                }
                """, "bot.LinkReader", LINK_READER));
        List<String> console = new java.util.ArrayList<>();
        org.kheperasim.sim.run.Simulation.builder().arena("lab").classpath(List.of(classes)).controller("Peeker").seed(1)
                .seconds(0.5).console(line -> {
                    synchronized (console) {
                        console.add(line.text());
                    }
                }).run();
        assertEquals(List.of("peek none|none|none|none|none my own|my own|my own|my own|my own"),
                console.stream().filter(l -> l.contains("peek ")).map(l -> l.substring(l.indexOf("peek "))).toList(),
                console.toString());
    }

    /** The entry itself may be reached through a link (a folder linked into the course's tree). */
    @Test
    void anEntryReachedThroughALinkReadsItsOwnFiles() throws Exception {
        Path classes = linkedEntry();
        Path link = dir.resolve("linked-classes");
        Files.createSymbolicLink(link, classes);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(link), getClass().getClassLoader())) {
            @SuppressWarnings("unchecked")
            java.util.function.Function<String, String> reader = (java.util.function.Function<String, String>)
                    loader.loadClass("bot.LinkReader").getConstructor().newInstance();
            assertEquals("my own|my own|my own|my own|my own", reader.apply("mine.txt"));
            assertEquals("none|none|none|none|none", reader.apply("passwd.txt"));
        }
    }

    /** A resource larger than the limit is not read into memory: not found, at once (a 3 GB sparse file). */
    @Test
    void aHugeResourceIsNotRead() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("classes")), Map.of("bot.LinkReader", LINK_READER));
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(classes.resolve("huge.bin").toFile(), "rw")) {
            f.setLength(3L << 30);
        }
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader())) {
            assertEquals(null, loader.ownResource("huge.bin"));
        }
    }

    @SuppressWarnings("unchecked")
    private String read(Path entry) throws Exception {
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(entry), getClass().getClassLoader())) {
            return ((Supplier<String>) loader.loadClass("bot.Reader").getConstructor().newInstance()).get();
        }
    }

    @Test
    void aTrustedControllerReadsAsJavaDoes() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("classes")), Map.of("bot.Reader", READER));
        Files.writeString(classes.resolve("bot/config.properties"), "speed=7\n");
        Files.writeString(classes.resolve("top.txt"), "top\n");
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader(), false)) {
            @SuppressWarnings("unchecked")
            String read = ((Supplier<String>) loader.loadClass("bot.Reader").getConstructor().newInstance()).get();
            List<String> answers = List.of(read.split(","));
            assertEquals("#", answers.get(8).substring(0, 1), "the simulator's allowlist, through the parent: " + read);
            assertEquals("none", answers.get(7), "String's loader does not see the controller's entry: " + read);
        }
    }
}
