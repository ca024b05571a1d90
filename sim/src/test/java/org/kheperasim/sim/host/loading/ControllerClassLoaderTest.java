package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.IntSupplier;
import java.util.function.Supplier;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.Controller;
import org.kheperasim.sim.host.SimClock;
import org.kheperasim.sim.host.SimClockTestHooks;
import org.kheperasim.testfixtures.loading.BundledSleeper;

class ControllerClassLoaderTest {
    private static final long MS = 1_000_000L;

    /** Generous: rewritten sleeps take microseconds, the sleeps asked for take up to two hours. */
    private static final Duration REAL_TIME_LIMIT = Duration.ofSeconds(10);

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final List<ControllerClassLoader> loaders = new ArrayList<>();

    @BeforeEach
    void bindClock() {
        SimClock.bind(clock);
    }

    @AfterEach
    void unbindClock() throws IOException {
        SimClock.unbind();
        for (ControllerClassLoader loader : loaders) {
            loader.close();
        }
    }

    private ControllerClassLoader loader(Path... classpath) {
        ControllerClassLoader loader = new ControllerClassLoader(List.of(classpath), getClass().getClassLoader());
        loaders.add(loader);
        return loader;
    }

    private Path compile(String directory, Map<String, String> sources) throws IOException {
        return JavaSources.compile(Files.createDirectories(dir.resolve(directory)), sources);
    }

    /** Construct with the no-argument constructor and run on this thread, which has the fake clock. */
    private static void run(Class<?> type) throws ReflectiveOperationException {
        ((Runnable) type.getConstructor().newInstance()).run();
    }

    /**
     * Run on a thread of its own with the fake clock, and fail (rather than wait out a real sleep)
     * when that takes real time.
     */
    private void runInNoRealTime(Class<?> type) {
        assertTimeoutPreemptively(REAL_TIME_LIMIT, () -> {
            SimClock.bind(clock);
            try {
                run(type);
            } finally {
                SimClock.unbind();
            }
        });
    }

    @Test
    void threadSleepSleepsOnTheSimulatedClock() throws Exception {
        Path classes = compile("classes", Map.of("Sleeper", """
                public class Sleeper extends Thread {
                    @Override public void run() {
                        try {
                            Thread.sleep(100);
                            Thread.sleep(3_600_000);
                            Thread.sleep(2, 500);
                        } catch (InterruptedException e) {
                            throw new IllegalStateException(e);
                        }
                    }
                }
                """));

        runInNoRealTime(loader(classes).loadClass("Sleeper"));

        assertEquals(List.of(100 * MS, 3_600_000 * MS, 2 * MS + 500), clock.sleeps());
    }

    @Test
    void unqualifiedSleepInAThreadSubclassSleepsOnTheSimulatedClock() throws Exception {
        Path classes = compile("classes", Map.of("Robot", """
                public class Robot extends Thread {
                    @Override public void run() {
                        try {
                            sleep(100);
                            sleep(1, 1);
                            Robot.yield();
                            onSpinWait();
                        } catch (InterruptedException e) {
                            throw new IllegalStateException(e);
                        }
                    }
                }
                """));

        runInNoRealTime(loader(classes).loadClass("Robot"));

        assertEquals(List.of(100 * MS, MS + 1), clock.sleeps());
        assertEquals(2, clock.pauses());
    }

    @Test
    void unqualifiedSleepBelowAnIntermediateClassOrTheApiControllerIsRewritten() throws Exception {
        Path classes = compile("classes", Map.of(
                "Base", "public class Base extends Thread { }",
                "Derived", """
                        public class Derived extends Base {
                            @Override public void run() {
                                try { sleep(7); } catch (InterruptedException e) { throw new IllegalStateException(e); }
                            }
                        }
                        """,
                "ApiBot", """
                        public class ApiBot extends org.kheperasim.api.Controller {
                            public static void nap() throws InterruptedException { sleep(9); }
                            @Override protected void doWork() { }
                        }
                        """));
        ControllerClassLoader loader = loader(classes);

        runInNoRealTime(loader.loadClass("Derived"));
        Class<?> apiBot = loader.loadClass("ApiBot");
        apiBot.getMethod("nap").invoke(null);

        assertEquals(List.of(7 * MS, 9 * MS), clock.sleeps());
        assertSame(Controller.class, apiBot.getSuperclass());
    }

    @Test
    void timeUnitSleepSleepsOnTheSimulatedClock() throws Exception {
        Path classes = compile("classes", Map.of("Patient", """
                import java.util.concurrent.TimeUnit;
                public class Patient implements Runnable {
                    @Override public void run() {
                        try {
                            TimeUnit.MILLISECONDS.sleep(5);
                            TimeUnit.HOURS.sleep(2);
                        } catch (InterruptedException e) {
                            throw new IllegalStateException(e);
                        }
                    }
                }
                """));

        runInNoRealTime(loader(classes).loadClass("Patient"));

        assertEquals(List.of(5 * MS, TimeUnit.HOURS.toNanos(2)), clock.sleeps());
    }

    @Test
    void clockReadsReturnTheSimulatedTime() throws Exception {
        Path classes = compile("classes", Map.of("Watch", """
                import java.util.function.LongSupplier;
                import java.util.function.Supplier;
                public class Watch implements Supplier<long[]> {
                    @Override public long[] get() {
                        LongSupplier millis = System::currentTimeMillis;
                        LongSupplier nanos = System::nanoTime;
                        return new long[] {
                            System.currentTimeMillis(), System.nanoTime(), millis.getAsLong(), nanos.getAsLong() };
                    }
                }
                """));

        @SuppressWarnings("unchecked")
        Supplier<long[]> watch = (Supplier<long[]>) loader(classes).loadClass("Watch").getConstructor().newInstance();

        long[] expected = {FakeClock.EPOCH_MILLIS, FakeClock.START_NANOS, FakeClock.EPOCH_MILLIS, FakeClock.START_NANOS};
        assertArrayEquals(expected, watch.get());
    }

    @Test
    void aClassWithItsOwnSleepKeepsCallingIt() throws Exception {
        Path classes = compile("classes", Map.of(
                "OwnSleep", """
                        public class OwnSleep extends Thread {
                            public static int calls;
                            public static void sleep(long millis) { calls++; }
                            @Override public void run() {
                                sleep(100);
                                try { sleep(3, 0); } catch (InterruptedException e) { throw new IllegalStateException(e); }
                            }
                        }
                        """,
                "OwnSleepChild", """
                        public class OwnSleepChild extends OwnSleep {
                            @Override public void run() { sleep(50); }
                        }
                        """,
                "Util", "public class Util { public static void sleep(long millis) { OwnSleep.calls++; } }",
                "UsesUtil", """
                        public class UsesUtil implements Runnable {
                            @Override public void run() { Util.sleep(5); OwnSleep.sleep(5); }
                        }
                        """));
        ControllerClassLoader loader = loader(classes);

        run(loader.loadClass("OwnSleep"));
        run(loader.loadClass("OwnSleepChild"));
        run(loader.loadClass("UsesUtil"));

        assertEquals(4, loader.loadClass("OwnSleep").getField("calls").getInt(null));
        assertEquals(List.of(3 * MS), clock.sleeps(), "only sleep(long, int), which OwnSleep does not declare");
    }

    @Test
    void aRunawayLoopStopsAtItsCheckpoint() throws Exception {
        Path classes = compile("classes", Map.of("Spinner", """
                public class Spinner extends Thread {
                    public volatile long x;
                    @Override public void run() {
                        while (true) {
                            x++;
                        }
                    }
                }
                """));
        Class<?> type = loader(classes).loadClass("Spinner");
        Thread spinner = (Thread) type.getConstructor().newInstance();
        AtomicReference<Throwable> ended = new AtomicReference<>();
        Thread host = new Thread(() -> {
            SimClock.bind(clock);
            try {
                spinner.run();
            } catch (Throwable t) {
                ended.set(t);
            } finally {
                SimClock.unbind();
            }
        }, "spinner host");
        host.setDaemon(true); // should the test fail, the loop must not keep the JVM alive
        host.start();
        long deadline = System.nanoTime() + REAL_TIME_LIMIT.toNanos();
        while (type.getField("x").getLong(spinner) == 0 && System.nanoTime() < deadline) {
            Thread.onSpinWait();
        }

        clock.requestStop();
        SimClockTestHooks.stopRequested();
        try {
            host.join(REAL_TIME_LIMIT.toMillis());
        } finally {
            SimClockTestHooks.stopSettled();
        }

        assertFalse(host.isAlive(), "the loop did not stop");
        assertInstanceOf(FakeClock.Stop.class, ended.get());
        assertTrue(type.getField("x").getLong(spinner) > 0);
    }

    @Test
    void nestedAnonymousAndLambdaCodeIsRewrittenToo() throws Exception {
        Path classes = compile("classes", Map.of("Outer", """
                import java.util.concurrent.Callable;
                public class Outer extends Thread {
                    static class Nested {
                        void nap() throws InterruptedException { Thread.sleep(1); }
                    }
                    @Override public void run() {
                        try {
                            new Nested().nap();
                            new Object() {
                                void nap() throws InterruptedException { Thread.sleep(2); }
                            }.nap();
                            Callable<Void> lambda = () -> { Thread.sleep(3); return null; };
                            lambda.call();
                        } catch (Exception e) {
                            throw new IllegalStateException(e);
                        }
                    }
                }
                """));
        ControllerClassLoader loader = loader(classes);

        runInNoRealTime(loader.loadClass("Outer"));

        assertEquals(List.of(MS, 2 * MS, 3 * MS), clock.sleeps());
        assertSame(loader, loader.loadClass("Outer$Nested").getClassLoader());
        assertSame(loader, loader.loadClass("Outer$1").getClassLoader());
    }

    @Test
    void sharedClassesComeFromTheParentEvenWhenTheClasspathHasThem() throws Exception {
        Path classes = dir.resolve("classes");
        Files.createDirectories(classes.resolve("org/kheperasim/api"));
        Files.writeString(classes.resolve("org/kheperasim/api/Controller.class"), "never read");
        ControllerClassLoader loader = loader(classes);

        assertSame(Controller.class, loader.loadClass("org.kheperasim.api.Controller"));
        assertSame(SimClock.class, loader.loadClass("org.kheperasim.sim.host.SimClock"));
        assertSame(String.class, loader.loadClass("java.lang.String"));
        assertSame(Test.class, loader.loadClass("org.junit.jupiter.api.Test"));
    }

    @Test
    void aClassInAJarLoadsWithTheJarAsItsCodeSource() throws Exception {
        Path classes = compile("classes", Map.of("jarbot.JarBot", """
                package jarbot;
                public class JarBot extends Thread {
                    @Override public void run() {
                        try { sleep(42); } catch (InterruptedException e) { throw new IllegalStateException(e); }
                    }
                }
                """));
        byte[] classFile = Files.readAllBytes(classes.resolve("jarbot/JarBot.class"));
        Path jar = dir.resolve("bot.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry("jarbot/JarBot.class"));
            out.write(classFile);
            out.putNextEntry(new JarEntry("jarbot/notes.txt"));
            out.write("turn left".getBytes(StandardCharsets.UTF_8));
        }
        ControllerClassLoader loader = loader(jar);

        Class<?> type = loader.loadClass("jarbot.JarBot");
        runInNoRealTime(type);

        assertEquals(List.of(42 * MS), clock.sleeps());
        assertSame(loader, type.getClassLoader());
        assertEquals(jar.toUri().toURL(), type.getProtectionDomain().getCodeSource().getLocation());
        URL resource = loader.getResource("jarbot/JarBot.class");
        assertNotNull(resource);
        assertEquals("jar", resource.getProtocol());
        try (InputStream in = resource.openStream()) {
            assertArrayEquals(classFile, in.readAllBytes());
        }
        try (InputStream in = loader.getResourceAsStream("jarbot/notes.txt")) {
            assertEquals("turn left", new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }

    @Test
    void eachLoaderDefinesItsOwnClassesAndSeesARecompiledClass() throws Exception {
        String source = """
                public class Version implements java.util.function.IntSupplier {
                    @Override public int getAsInt() { return %d; }
                }
                """;
        Path classes = compile("classes", Map.of("Version", source.formatted(1)));
        Class<?> first = loader(classes).loadClass("Version");
        Class<?> again = loader(classes).loadClass("Version");
        compile("classes", Map.of("Version", source.formatted(2)));
        Class<?> recompiled = loader(classes).loadClass("Version");

        assertNotSame(first, again);
        assertEquals(1, ((IntSupplier) first.getConstructor().newInstance()).getAsInt());
        assertEquals(2, ((IntSupplier) recompiled.getConstructor().newInstance()).getAsInt());
    }

    @Test
    void aCorruptClassFileIsReportedWithItsClassAndFile() throws Exception {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        Path broken = classes.resolve("Broken.class");
        Files.writeString(broken, "this is not a class file");
        compile("classes", Map.of("Whole", "public class Whole { void f() { for (int i = 0; i < 3; i++) { } } }"));
        byte[] whole = Files.readAllBytes(classes.resolve("Whole.class"));
        Path truncated = classes.resolve("Truncated.class");
        Files.write(truncated, Arrays.copyOf(whole, whole.length / 2));
        ControllerClassLoader loader = loader(classes);

        ClassFormatError notAClass = assertThrows(ClassFormatError.class, () -> loader.loadClass("Broken"));
        ClassFormatError cut = assertThrows(ClassFormatError.class, () -> loader.loadClass("Truncated"));

        assertTrue(notAClass.getMessage().contains("Broken") && notAClass.getMessage().contains(broken.toString()),
                notAClass.getMessage());
        assertTrue(cut.getMessage().contains("Truncated") && cut.getMessage().contains(truncated.toString()),
                cut.getMessage());
    }

    @Test
    void aClassFileInTheWrongDirectoryIsReportedWithItsFile() throws Exception {
        Path classes = compile("classes", Map.of("pkg.Misplaced", "package pkg; public class Misplaced { }"));
        Path misplaced = Files.copy(classes.resolve("pkg/Misplaced.class"), classes.resolve("Misplaced.class"));

        NoClassDefFoundError e = assertThrows(NoClassDefFoundError.class, () -> loader(classes).loadClass("Misplaced"));

        assertTrue(e.getMessage().contains(misplaced.toString()) && e.getMessage().contains("pkg/Misplaced"),
                e.getMessage());
    }

    @Test
    void aClassFileTooNewToRewriteSaysHowToCompile() throws Exception {
        Path classes = compile("classes", Map.of("Future", "public class Future { }"));
        Path file = classes.resolve("Future.class");
        byte[] bytes = Files.readAllBytes(file);
        bytes[6] = 0;
        bytes[7] = 99; // Java 55
        Files.write(file, bytes);

        UnsupportedClassVersionError e = assertThrows(UnsupportedClassVersionError.class,
                () -> loader(classes).loadClass("Future"));

        assertTrue(e.getMessage().contains("Future") && e.getMessage().contains(file.toString())
                && e.getMessage().contains("--release 17"), e.getMessage());
    }

    @Test
    void aClassFoundNowhereIsNotFound() {
        ControllerClassLoader loader = loader();

        assertThrows(ClassNotFoundException.class, () -> loader.loadClass("NoSuchRobot"));
    }

    @Test
    void aBundledControllerOnTheParentsClasspathIsRewrittenToo() throws Exception {
        ControllerClassLoader loader = loader();

        Class<?> bundled = loader.loadClass(BundledSleeper.class.getName());
        runInNoRealTime(bundled);

        assertNotSame(BundledSleeper.class, bundled);
        assertSame(loader, bundled.getClassLoader());
        assertEquals(List.of(100 * MS), clock.sleeps());
    }

    @Test
    void resourcesComeFromTheClasspathFirst() throws Exception {
        Path parentDir = Files.createDirectories(dir.resolve("parent"));
        Path childDir = Files.createDirectories(dir.resolve("child"));
        Files.writeString(parentDir.resolve("greeting.txt"), "parent");
        Files.writeString(parentDir.resolve("only-parent.txt"), "parent");
        Files.writeString(childDir.resolve("greeting.txt"), "child");
        try (URLClassLoader parent = new URLClassLoader(new URL[] {parentDir.toUri().toURL()}, getClass().getClassLoader());
                ControllerClassLoader loader = new ControllerClassLoader(List.of(childDir), parent)) {

            assertEquals(childDir.resolve("greeting.txt").toUri().toURL(), loader.getResource("greeting.txt"));
            assertEquals(List.of(childDir.resolve("greeting.txt").toUri().toURL(),
                            parentDir.resolve("greeting.txt").toUri().toURL()),
                    Collections.list(loader.getResources("greeting.txt")));
            assertEquals(parentDir.resolve("only-parent.txt").toUri().toURL(), loader.getResource("only-parent.txt"));
            // Controller code asks through ResourceHooks instead (ControllerResourcesTest): its own entry only.
            assertNull(loader.ownResource("only-parent.txt"));
            assertEquals("child", new String(loader.ownResource("greeting.txt"), StandardCharsets.UTF_8));
        }
    }

    @Test
    void aMissingClasspathEntryIsAnError() {
        Path missing = dir.resolve("no-such-dir");

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> loader(missing));

        assertTrue(e.getMessage().contains(missing.toString()), e.getMessage());
    }
}
