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
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;

/**
 * Student code cannot take the simulator down, harm the machine or fake a result: each hostile
 * controller runs headless and ends with a named fault (or is refused at load, naming its line),
 * the application stays alive, nothing is written outside, and its threads end with the run.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class HostileControllerTest {
    @TempDir
    static Path dir;
    static Path classes;
    static Path outside;

    private static final String[][] SOURCES = {
        {"Exiter", "setSpeeds(3, 3); sleepMillis(500); System.exit(0);"},
        {"Halter", "sleepMillis(100); Runtime.getRuntime().halt(0);"},
        {"ExitByReference", "java.util.function.IntConsumer e = System::exit; sleepMillis(100); e.accept(3);"},
        {"Writer", "try { java.nio.file.Files.writeString(java.nio.file.Path.of(TARGET), \"x\"); } catch (Exception e) { }"},
        {"Deleter", "new java.io.File(TARGET).delete(); sleepMillis(100);"},
        {"Networker", "try { new java.net.Socket(\"127.0.0.1\", 9).close(); } catch (Exception e) { } sleepMillis(100);"},
        {"Reflector", "try { Class<?> c = Class.forName(\"org.kheperasim.sim.engine.SimRobot\"); } catch (Exception e) { }"},
        {"Intruder", "org.kheperasim.sim.engine.model.Settings.class.getName(); sleepMillis(100);"},
        {"HandleBot", "try { java.lang.invoke.MethodHandles.lookup().findStatic(System.class, \"exit\","
            + " java.lang.invoke.MethodType.methodType(void.class, int.class)).invoke(0); } catch (Throwable t) { }"},
        {"Waiter", "synchronized (this) { try { wait(100); } catch (InterruptedException e) { } } setSpeeds(1, 1);"},
        {"WaitForever", "synchronized (this) { try { wait(); } catch (InterruptedException e) { } }"},
        {"Parker", "java.util.concurrent.locks.LockSupport.parkNanos(100_000_000L); setSpeeds(1, 1);"},
        {"Spinner", "if (!started) { started = true; new Thread(() -> { long n = 0; while (true) { n++; } }).start(); }"
            + " sleepMillis(100);"},
        {"Swallower", "while (true) { try { sleepMillis(10); } catch (Throwable t) { } }"},
        {"TrustedWriter", "try { java.nio.file.Files.writeString(java.nio.file.Path.of(TARGET + \".trusted\"), \"x\"); }"
            + " catch (Exception e) { } sleepMillis(100);"},
        {"Clockwatcher", "print(\"now \" + java.time.Instant.now()); sleepMillis(1000);"},
        {"NegativeSleeper", "try { Thread.sleep(-1); } catch (InterruptedException e) { } sleepMillis(100);"},
    };

    /** Whole classes: controllers whose construction throws or never returns. */
    private static final String[][] CLASSES = {
        {"InitThrower", "public class InitThrower extends Controller {\n    static final int V = Integer.parseInt(\"x\");\n"
            + "    @Override protected void doWork() { sleepMillis(V); }\n}\n"},
        {"CtorThrower", "public class CtorThrower extends StepController {\n"
            + "    public CtorThrower() { throw new IllegalStateException(\"no calibration\"); }\n"
            + "    @Override protected void step() { setSpeeds(1, 1); }\n}\n"},
        {"CtorLooper", "public class CtorLooper extends Controller {\n    static volatile long n;\n"
            + "    public CtorLooper() { while (n >= 0) { n++; } }\n    @Override protected void doWork() { sleepMillis(100); }\n}\n"},
        {"InitLooper", "public class InitLooper extends StepController {\n    static volatile long n;\n"
            + "    static { while (n >= 0) { n++; } }\n    @Override protected void step() { setSpeeds(1, 1); }\n}\n"},
    };

    @BeforeAll
    static void compile() throws IOException {
        classes = dir.resolve("classes");
        outside = dir.resolve("outside.txt");
        Files.writeString(outside, "keep me");
        Files.createDirectories(classes);
        List<String> files = new ArrayList<>();
        for (String[] s : SOURCES) {
            Path f = dir.resolve(s[0] + ".java");
            Files.writeString(f, "import org.kheperasim.api.*;\n\npublic class " + s[0] + " extends Controller {\n"
                    + "    static final String TARGET = \"" + outside.toString().replace("\\", "\\\\") + "\";\n"
                    + "    boolean started;\n\n"
                    + "    @Override\n    protected void doWork() {\n        " + s[1] + "\n    }\n}\n");
            files.add(f.toString());
        }
        for (String[] c : CLASSES) {
            Path f = dir.resolve(c[0] + ".java");
            Files.writeString(f, "import org.kheperasim.api.*;\n\n" + c[1]);
            files.add(f.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "-g", "--release", "17", "-proc:none"));
        args.addAll(files);
        assertEquals(0, javac.run(null, null, null, args.toArray(new String[0])), "the hostile controllers compile");
    }

    private record Outcome(RunResult result, List<String> console) {
        String text() {
            return String.join("\n", console);
        }
    }

    private static Outcome run(String controller, double seconds) {
        return run(controller, seconds, org.kheperasim.sim.host.HostOptions.defaults());
    }

    private static Outcome run(String controller, double seconds, org.kheperasim.sim.host.HostOptions options) {
        List<String> console = new ArrayList<>();
        RunResult r = Simulation.builder().arena("lab").classpath(List.of(classes)).controller(controller).seed(1)
                .seconds(seconds).hostOptions(options).console((ConsoleLine line) -> {
                    synchronized (console) {
                        console.add(line.text());
                    }
                }).run();
        return new Outcome(r, console);
    }

    private static void brokeRule(String controller, String named) {
        Outcome o = run(controller, 10);
        assertEquals(ControllerStatus.BROKE_RULE, o.result.first().status(), controller + ": " + o.text());
        assertTrue(o.text().contains(named), controller + " names the fault '" + named + "': " + o.text());
    }

    @Test
    void aConstructorOrStaticInitializerThatThrowsIsNamedWithItsLine() {
        ControllerException init = assertThrows(ControllerException.class, () -> run("InitThrower", 1));
        assertTrue(init.getMessage().startsWith("A static initializer of controller InitThrower threw"
                + " java.lang.NumberFormatException: For input string: \"x\" at InitThrower.java:4;"), init.getMessage());
        ControllerException ctor = assertThrows(ControllerException.class, () -> run("CtorThrower", 1));
        assertTrue(ctor.getMessage().startsWith("The constructor of controller CtorThrower threw"
                + " java.lang.IllegalStateException: no calibration at CtorThrower.java:4;"), ctor.getMessage());
    }

    @Test
    void aConstructorOrStaticInitializerThatNeverReturnsIsStoppedAndNamed() {
        for (String c : List.of("CtorLooper", "InitLooper")) {
            ControllerException e = assertThrows(ControllerException.class, () -> Simulation.builder().arena("lab")
                    .classpath(List.of(classes)).controller(c).seed(1).seconds(1)
                    .hostOptions(org.kheperasim.sim.host.HostOptions.defaults().withHangTimeout(500_000_000L)).run(), c);
            assertTrue(e.getMessage().contains("controller " + c + " (" + c + ") was not constructed: its constructor or a"
                    + " static initializer ran for 0.5 s of real time without returning"), e.getMessage());
        }
    }

    @Test
    void exitAndHaltEndTheRunWithANamedFaultAndTheApplicationStays() {
        brokeRule("Exiter", "called System.exit(0)");
        brokeRule("Halter", "called Runtime.halt(0)");
        brokeRule("ExitByReference", "called System.exit(3)");
    }

    @Test
    void filesNetworkReflectionAndTheSimulatorAreRefusedAtLoadNamingTheLine() throws IOException {
        for (String[] c : new String[][] {{"Writer", "java.nio.file."}, {"Deleter", "java.io.File"},
            {"Networker", "java.net.Socket"}, {"Reflector", "java.lang.Class.forName"},
            {"Intruder", "org.kheperasim.sim.engine.model.Settings"}, {"HandleBot", "java.lang.invoke.MethodHandles.lookup()"}}) {
            ControllerException e = assertThrows(ControllerException.class, () -> run(c[0], 1), c[0]);
            assertTrue(e.getMessage().contains(c[1]), c[0] + " names the call: " + e.getMessage());
            assertTrue(e.getMessage().contains(c[0] + ".java:"), c[0] + " names the student's line: " + e.getMessage());
        }
        assertEquals("keep me", Files.readString(outside), "nothing outside was touched");
    }

    @Test
    void aControllerTheUserTrustsRunsUncontained() throws IOException {
        assertThrows(ControllerException.class, () -> run("TrustedWriter", 1), "contained by default");
        RunResult r = Simulation.builder().arena("lab").classpath(List.of(classes)).controller("TrustedWriter").seed(1)
                .seconds(1).trusted(true).run();
        assertEquals(ControllerStatus.STOPPED, r.first().status());
        assertEquals("x", Files.readString(Path.of(outside + ".trusted")), "a trusted controller may write files");
    }

    @Test
    void waitingAndParkingPassSimulatedTime() {
        for (String c : List.of("Waiter", "Parker")) {
            Outcome o = run(c, 20);
            assertEquals(ControllerStatus.STOPPED, o.result.first().status(), c + " ran to the end: " + o.text());
            assertEquals(20, o.result.simulatedSeconds(), 0.01);
            assertTrue(o.result.first().distanceMm() > 100, c + " drove: it was not stalled");
        }
        brokeRule("WaitForever", "called Object.wait() with no timeout");
    }

    @Test
    void anExceptionThrownInsideTheSimulatorStillShowsTheStudentsLine() {
        Outcome o = run("NegativeSleeper", 1);
        assertEquals(ControllerStatus.FAILED, o.result.first().status(), o.text());
        assertTrue(o.text().contains("IllegalArgumentException") && o.text().contains("at NegativeSleeper.doWork(NegativeSleeper.java:"),
                "the student's frame below the simulator's: " + o.text());
        assertFalse(o.text().contains("at org.kheperasim.sim."), "the simulator's frames are left out: " + o.text());
    }

    @Test
    void theWallClockIsTheSimulatedOne() {
        Outcome o = run("Clockwatcher", 3);
        assertTrue(o.text().contains("now 2001-07-27T11:06:0"), "Instant.now() reads robot time: " + o.text());
    }

    @Test
    void threadsAControllerStartsEndWithTheRunAndCatchAllLoopsStop() throws InterruptedException {
        java.util.Set<Thread> before = Thread.getAllStackTraces().keySet();
        // A hang is declared after a timeout of real time: 1 s, not the default 5 s, for the one expected to hang.
        Outcome spinner = run("Spinner", 5, SPINNER_HANG);
        Outcome swallower = run("Swallower", 5);
        assertEquals(ControllerStatus.STOPPED, swallower.result.first().status(), swallower.text());
        assertFalse(swallower.text().contains("left behind"), swallower.text());
        assertFalse(spinner.text().contains("left behind"), spinner.text());
        // The thread it started runs in the lockstep: spinning without an API call, it hangs the controller.
        assertEquals(ControllerStatus.HUNG, spinner.result.first().status(), spinner.text());
        assertTrue(spinner.text().contains("that it started)"), "the hung thread is named: " + spinner.text());
        assertThreadsBackTo(before, "after the runs");
    }

    /**
     * Daemon threads that live as long as the JVM once started, whichever test starts them first: the
     * simulator's watchdog of constructions and steps, JNA's cleaner, the JDK's process reaper, and
     * (virtual controller threads, Java 21+) the JDK's unblocker of timed virtual-thread waits.
     */
    /** The Spinner hangs by design: it is declared hung after 1 s of real time, not the default 5 s. */
    private static final org.kheperasim.sim.host.HostOptions SPINNER_HANG = org.kheperasim.sim.host.HostOptions.defaults()
            .withHangTimeout(TimeUnit.SECONDS.toNanos(1));

    private static final java.util.Set<String> SERVICE_THREADS = java.util.Set.of("khepera-step-watchdog", "JNA Cleaner",
            "process reaper", "VirtualThread-unblocker");

    /** Every thread started since {@code before} has ended, but the JVM's service threads (generous: threads take a moment to end). */
    private static void assertThreadsBackTo(java.util.Set<Thread> before, String when) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        List<String> left;
        do {
            Thread.sleep(50);
            left = Thread.getAllStackTraces().keySet().stream()
                    .filter(t -> !before.contains(t) && !(t.isDaemon() && SERVICE_THREADS.contains(t.getName())))
                    .map(Thread::getName).toList();
        } while (!left.isEmpty() && System.nanoTime() < deadline);
        assertTrue(left.isEmpty(), "threads still alive " + when + ": " + left);
    }

    /**
     * The window drives a run through a {@link PacedRunner} on its own thread: the same hostile
     * controllers end there with their fault, the runner (the window's run) stays usable, and the
     * controllers' threads are gone after a stop.
     */
    @Test
    void inAWindowSessionTheFaultIsNamedAndTheWindowsRunGoesOn() throws Exception {
        java.util.Set<Thread> before = Thread.getAllStackTraces().keySet();
        for (String[] c : new String[][] {{"Exiter", "BROKE_RULE"}, {"Halter", "BROKE_RULE"},
            {"ExitByReference", "BROKE_RULE"}, {"WaitForever", "BROKE_RULE"}, {"Waiter", "RUNNING"},
            {"Parker", "RUNNING"}, {"Spinner", "HUNG"}, {"Swallower", "RUNNING"}}) {
            List<String> console = new ArrayList<>();
            RunSession s = new RunSession(org.kheperasim.sim.arena.ArenaFormat.loadBundled("lab"), c[0],
                    new ControllerCatalog(List.of(classes)), 1, org.kheperasim.sim.engine.model.Settings.defaults(),
                    line -> {
                        synchronized (console) {
                            console.add(line.text());
                        }
                    }, c[0].equals("Spinner") ? SPINNER_HANG : org.kheperasim.sim.host.HostOptions.defaults());
            PacedRunner runner = new PacedRunner(s, null);
            runner.setSpeed(PacedRunner.MAX_SPEED);
            runner.pauseAt(3_000_000_000L);
            runner.start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (runner.latest().timeNanos() < 3_000_000_000L && !s.status().ended() && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            assertEquals(c[1], s.status().name(), c[0] + " in the window's run: " + console);
            if (c[1].equals("RUNNING")) {
                assertEquals(3_000_000_000L, runner.latest().timeNanos(), c[0] + ": the window's run reached its pause, not stalled");
            }
            assertTrue(runner.failure() == null, c[0] + " did not break the window's run: " + runner.failure());
            assertTrue(runner.stopAndWait(10_000), c[0] + ": the window can stop the run");
            s.close();
        }
        assertThreadsBackTo(before, "after the window's runs");
        for (String refused : List.of("Writer", "Deleter", "Networker", "Reflector", "Intruder", "HandleBot")) {
            assertThrows(ControllerException.class, () -> new RunSession(org.kheperasim.sim.arena.ArenaFormat.loadBundled("lab"),
                    refused, new ControllerCatalog(List.of(classes)), 1, org.kheperasim.sim.engine.model.Settings.defaults(),
                    line -> { }, org.kheperasim.sim.host.HostOptions.defaults()),
                    refused + " is refused when the window starts it, as headless");
        }
    }

    /** The window's Stop ends a run whose controller loops without an API call at once, not after the hang timeout. */
    @Test
    void theWindowsStopEndsALoopingControllerAtOnce() throws Exception {
        List<String> console = new java.util.concurrent.CopyOnWriteArrayList<>();
        long began = System.nanoTime();
        RunSession s = new RunSession(org.kheperasim.sim.arena.ArenaFormat.loadBundled("lab"), "org.kheperasim.testcontrollers.Looper",
                new ControllerCatalog(List.of()), 1, org.kheperasim.sim.engine.model.Settings.defaults(), line -> console.add(line.format()),
                org.kheperasim.sim.host.HostOptions.defaults().withHangTimeout(TimeUnit.SECONDS.toNanos(60)));
        PacedRunner runner = new PacedRunner(s, null);
        runner.setSpeed(PacedRunner.MAX_SPEED);
        runner.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (console.stream().noneMatch(l -> l.endsWith("looping")) && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        Thread.sleep(300); // it loops now, holding the turn
        // Generous for a busy machine; a hang would take the 60 s of the timeout.
        assertTrue(runner.stopAndWait(30_000), "the window's Stop ended the run");
        assertEquals("STOPPED", s.status().name(), (System.nanoTime() - began) / 1e9 + " s: " + console);
        assertTrue(runner.latest().timeNanos() >= 1_000_000_000L, "it was stopped in its loop, after its first second");
        assertEquals(PacedRunner.State.STOPPED, runner.state(), "the window says the run was stopped, not that it ended");
        s.close();
    }

    @Test
    void theCommandLineExitsNonZeroWithTheResultLineForAFaultAndForAHog() throws Exception {
        Path hog = dir.resolve("Hog.java");
        Files.writeString(hog, "import org.kheperasim.api.*;\nimport java.util.*;\n\npublic class Hog extends Controller {\n"
                + "    final List<long[]> kept = new ArrayList<>();\n\n    @Override\n    protected void doWork() {\n"
                + "        kept.add(new long[1 << 16]);\n        setSpeeds(1, 1);\n    }\n}\n");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("java.class.path"), "-d", classes.toString(), "--release", "17", hog.toString()));
        // The Hog three times: whether the heap watch or the heap running out stops it first depends on
        // the collector's timing, and either way the run must still print its result line.
        String[] hogCase = {"Hog", "allocated without bound"};
        for (String[] c : new String[][] {{"Exiter", "System.exit"}, hogCase, hogCase, hogCase}) {
            // The quick compiler only: the JVM lives a second or two (see gui/GuiEndToEndTest.childJvm).
            Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx64m",
                    "-XX:TieredStopAtLevel=1",
                    "-cp", System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "run", "--arena", "lab",
                    "--classpath", classes.toString(), "--controller", c[0], "--seconds", "60")
                    .redirectErrorStream(true).start();
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            p.getInputStream().transferTo(out);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), c[0] + " ends");
            String text = out.toString(StandardCharsets.UTF_8);
            assertEquals(1, p.exitValue(), c[0] + " fails the run: " + text);
            assertTrue(text.contains(c[1]), c[0] + " names the fault: " + text);
            assertTrue(text.toLowerCase(Locale.ROOT).contains(c[0].toLowerCase(Locale.ROOT) + " in lab:"),
                    c[0] + " still prints the result line: " + text);
        }
    }
}
