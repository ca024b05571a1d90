package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;

/**
 * A controller that overrides the methods of its {@code Thread} (or the Appendix's
 * {@code killControl()}) to spin, throw or block runs as the same controller without the
 * override: the simulator never calls them on its own threads (it starts, interrupts and watches
 * a thread of its own that runs the controller's code, and the controller's own thread calls
 * {@code killControl()} when it sees the stop). Each run ends, with the same status and the same
 * trace as the plain controller's.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class OverridingControllerTest {
    @TempDir
    static Path dir;
    static Path classes;

    /** The Appendix's shape: a loop on a flag that killControl() clears. */
    private static final String DRIVER = """
            private final CurrentRobotState data;
            private volatile boolean active = true;
            static volatile long n;

            public %s(CurrentRobotState data, MessagePasser mp) {
                this.data = data;
            }

            public void killControl() {
                %s
            }

            @Override
            public void run() {
                Motor m = data.getMotorState();
                Sensor[] s = data.getSensorValues();
                long steps = 0;
                while (active) {
                    int front = Math.max(s[2].getDistValue(), s[3].getDistValue());
                    if (front > 500) {
                        m.setMotorSpeeds(-3, 3);
                    } else {
                        m.setMotorSpeeds(5, 4);
                    }
                    try {
                        Thread.sleep(100);
                    } catch (InterruptedException e) {
                        // go on
                    }
                    steps++;
                    %s
                }
            }
            """;

    private static final String SPIN = "while (n >= 0) { n++; }";
    /**
     * Spins inside the JDK, where no loop checkpoint of the controller's code can end it, until its
     * thread is interrupted (the simulator lets it go after its grace, and interrupts it).
     */
    private static final String LIBRARY_SPIN = "java.util.stream.LongStream.range(0, Long.MAX_VALUE).map(x -> {"
            + " if (Thread.interrupted()) { throw new IllegalStateException(\"interrupted\"); } return x * 31; }).sum();";

    /** Name, what the loop does at the end of each step, the overrides, and killControl()'s body if not the plain one. */
    private static final String[][] CONTROLLERS = {
        {"Plain", "", ""},
        {"KillSpins", "", "", "active = false; " + SPIN},
        {"KillThrows", "", "", "throw new IllegalStateException(\"not now\");"},
        {"KillJoins", "", "", "active = false; try { join(); } catch (InterruptedException e) { }"},
        {"KillSpinsInALibrary", "", "", LIBRARY_SPIN + " active = false;"},
        {"StartSpins", "", "@Override public void start() { " + SPIN + " }"},
        {"StateSpins", "", "@Override public State getState() { " + SPIN + " return State.NEW; }"},
        {"StateThrows", "", "@Override public State getState() { throw new IllegalStateException(\"no state\"); }"},
        {"TraceThrows", "", "@Override public StackTraceElement[] getStackTrace() { throw new IllegalStateException(); }"},
        {"ObjectThrows", "", "@Override public String toString() { throw new IllegalStateException(\"no name\"); }\n"
            + "@Override public int hashCode() { " + SPIN + " return 1; }\n"
            + "@Override public boolean equals(Object o) { throw new IllegalStateException(\"no equals\"); }"},
        {"HandlerIgnored", "", "@Override public void setUncaughtExceptionHandler(UncaughtExceptionHandler h) { }"},
        // Throws at 5 s of simulated time.
        {"Quits", "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }", ""},
        {"QuitsHandlerSpins", "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }",
            "@Override public UncaughtExceptionHandler getUncaughtExceptionHandler() { " + SPIN + " return null; }"},
        {"QuitsHandlerThrows", "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }",
            "@Override public UncaughtExceptionHandler getUncaughtExceptionHandler() { throw new IllegalStateException(); }"},
        {"QuitsHandlerNull", "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }",
            "@Override public UncaughtExceptionHandler getUncaughtExceptionHandler() { return null; }"},
        {"QuitsHandlerIgnored", "if (steps == 50) { throw new IllegalStateException(\"gave up\"); }",
            "@Override public void setUncaughtExceptionHandler(UncaughtExceptionHandler h) { }"},
        // Throws an exception whose own methods spin or throw on any thread but the one that threw it.
        {"QuitsOddly", "if (steps == 50) { throw new Odd(\"gave up\"); }",
            "static class Odd extends IllegalStateException {\n"
                + "    final Thread where = Thread.currentThread();\n"
                + "    Odd(String m) { super(m); }\n"
                + "    @Override public String toString() { if (Thread.currentThread() != where) { " + SPIN + " } return super.toString(); }\n"
                + "    @Override public String getMessage() { if (Thread.currentThread() != where) { throw new IllegalStateException(); }"
                + " return super.getMessage(); }\n"
                + "    @Override public StackTraceElement[] getStackTrace() { if (Thread.currentThread() != where) {"
                + " throw new IllegalStateException(); } return super.getStackTrace(); }\n"
                + "}"},
        // Hangs at 3 s of simulated time: the watchdog stops it (and interrupts its thread).
        {"Hangs", "if (steps == 30) { " + SPIN + " }", ""},
        {"HangsInterruptSpins", "if (steps == 30) { " + SPIN + " }", "@Override public void interrupt() { " + SPIN + " }"},
        {"HangsInterruptThrows", "if (steps == 30) { " + SPIN + " }",
            "@Override public void interrupt() { throw new IllegalStateException(\"not me\"); }"},
        {"HangsInterruptedSpins", "if (steps == 30) { " + SPIN + " }",
            "@Override public boolean isInterrupted() { " + SPIN + " return false; }"},
    };

    /**
     * A controller with a helper thread, looking at both threads the ways contained code may: who
     * is current, alive, interrupted, in which state; an interrupt before start, join, interrupting
     * itself. The placeholders take the overrides of the helper's class and of the controller's.
     */
    private static final String CREW = """
            import org.kheperasim.api.*;

            public class %1$s extends Thread {
                private final CurrentRobotState data;
                private final MessagePasser mp;
                volatile int seen;
                volatile boolean stopping;

                public %1$s(CurrentRobotState data, MessagePasser mp) {
                    this.data = data;
                    this.mp = mp;
                }

                class Helper extends Thread {
                    @Override
                    public void run() {
                        mp.sendMessage("helper current " + (Thread.currentThread() == this) + " alive " + isAlive()
                                + " state " + getState() + " interrupted " + isInterrupted());
                        try {
                            while (true) {
                                seen++;
                                Thread.sleep(30);
                            }
                        } catch (InterruptedException e) {
                            mp.sendMessage("helper interrupted after " + seen + ", flag " + isInterrupted());
                        }
                    }
                    %2$s
                }

                @Override
                public void run() {
                    mp.sendMessage("main current " + (Thread.currentThread() == this) + " state " + getState());
                    Helper early = new Helper();
                    early.interrupt();
                    early.start();
                    Helper h = new Helper();
                    mp.sendMessage("helper before start: alive " + h.isAlive() + " state " + h.getState());
                    h.start();
                    Motor m = data.getMotorState();
                    try {
                        Thread.sleep(1);
                        mp.sendMessage("helper started: alive " + h.isAlive() + " state " + h.getState());
                        for (int i = 0; i < 20; i++) {
                            m.setMotorSpeeds(3 + seen %% 4, 3);
                            Thread.sleep(100);
                        }
                        h.interrupt();
                        h.join();
                        early.join(1000);
                        mp.sendMessage("helper joined: alive " + h.isAlive() + " state " + h.getState() + " seen " + seen);
                    } catch (InterruptedException e) {
                        mp.sendMessage("main interrupted too soon");
                    }
                    interrupt();
                    try {
                        Thread.sleep(10);
                    } catch (InterruptedException e) {
                        mp.sendMessage("main saw its own interrupt, flag " + isInterrupted());
                    }
                    while (true) {
                        m.setMotorSpeeds(4, 5);
                        try {
                            Thread.sleep(100);
                        } catch (InterruptedException e) {
                            // go on
                        }
                    }
                }
                %3$s
            }
            """;

    /** Name, the helper's overrides, the controller's overrides. */
    private static final String[][] CREWS = {
        {"Crew", "", ""},
        {"CrewOverriding",
            "@Override public void interrupt() { stopping = true; super.interrupt(); }\n"
                + "@Override public synchronized void start() { seen += 0; super.start(); }\n"
                + "@Override public String toString() { throw new IllegalStateException(); }\n"
                + "@Override public int hashCode() { throw new IllegalStateException(); }",
            "@Override public String toString() { throw new IllegalStateException(); }\n"
                + "@Override public boolean equals(Object o) { throw new IllegalStateException(); }\n"
                + "@Override public void interrupt() { super.interrupt(); }"},
    };

    @BeforeAll
    static void compile() throws IOException {
        classes = dir.resolve("classes");
        Files.createDirectories(classes);
        List<String> files = new ArrayList<>();
        for (String[] c : CONTROLLERS) {
            Path f = dir.resolve(c[0] + ".java");
            Files.writeString(f, "import org.kheperasim.api.*;\n\npublic class " + c[0] + " extends Thread {\n"
                    + DRIVER.formatted(c[0], c.length > 3 ? c[3] : "active = false;", c[1]) + "\n" + c[2] + "\n}\n");
            files.add(f.toString());
        }
        for (String[] c : CREWS) {
            Path f = dir.resolve(c[0] + ".java");
            Files.writeString(f, CREW.formatted(c[0], c[1], c[2]));
            files.add(f.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "-g", "--release", "17", "-proc:none"));
        args.addAll(files);
        assertEquals(0, javac.run(null, null, null, args.toArray(new String[0])), "the controllers compile");
    }

    /** A run's result, its console, and its trace with the controller's name as {@code C}. */
    private record Outcome(RunResult result, List<String> console, String trace) {
        String text() {
            return String.join("\n", console);
        }
    }

    private static Outcome run(String controller) {
        List<String> console = new ArrayList<>();
        Path trace = dir.resolve(controller + ".trace");
        HostOptions options = controller.startsWith("Hangs") ? HostOptions.defaults().withHangTimeout(1_000_000_000L)
                : HostOptions.defaults();
        RunResult r = Simulation.builder().arena("lab").classpath(List.of(classes)).controller(controller).seed(1)
                .seconds(20).trace(trace).hostOptions(options)
                .console((ConsoleLine line) -> {
                    synchronized (console) {
                        console.add(line.text().replace(controller, "C"));
                    }
                }).run();
        try {
            return new Outcome(r, console, Files.readString(trace).replace(controller, "C"));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Runs {@code controller} and checks it ends as {@code plain} did: same status, same simulated time, same trace. */
    private static Outcome assertLike(Outcome plain, String controller) {
        Outcome o = run(controller);
        String why = controller + " ends as " + plain.result.controller() + " does: " + o.text();
        assertEquals(plain.result.simulatedSeconds(), o.result.simulatedSeconds(), 0, why);
        assertEquals(plain.result.first().status(), o.result.first().status(), why);
        assertTrue(o.trace.length() > 1000, why);
        assertTrue(plain.trace.equals(o.trace), "the same trace: " + why);
        assertEquals(plain.result.first().x(), o.result.first().x(), 0, why);
        assertEquals(plain.result.first().y(), o.result.first().y(), 0, why);
        assertTrue(!o.text().contains("this is a bug"), why);
        return o;
    }

    @Test
    void overridesOfThreadsMethodsAndOfKillControlChangeNothing() {
        Outcome plain = run("Plain");
        assertEquals(ControllerStatus.STOPPED, plain.result.first().status(), plain.text());
        assertEquals(20, plain.result.simulatedSeconds(), 0, plain.text());
        for (String c : List.of("KillSpins", "KillThrows", "KillJoins", "StartSpins", "StateSpins", "StateThrows",
                "TraceThrows", "ObjectThrows", "HandlerIgnored")) {
            Outcome o = assertLike(plain, c);
            assertEquals(plain.console, o.console, c + " says what the plain controller says");
        }
    }

    @Test
    void aKillControlThatNeverReturnsLeavesTheControllerBehindNotTheRun() {
        Outcome plain = run("Plain");
        Outcome o = assertLike(plain, "KillSpinsInALibrary");
        // It runs on the controller's own thread, which is let go after the grace: the run ends as it would.
        assertTrue(o.text().contains("did not stop within 2 s of being asked; it was left behind"), o.text());
    }

    @Test
    void whatTheControllerThrowsIsReportedWhateverItsHandlerMethodsDo() {
        Outcome plain = run("Quits");
        assertEquals(ControllerStatus.FAILED, plain.result.first().status(), plain.text());
        assertTrue(plain.text().contains("threw java.lang.IllegalStateException: gave up"), plain.text());
        for (String c : List.of("QuitsHandlerSpins", "QuitsHandlerThrows", "QuitsHandlerNull", "QuitsHandlerIgnored")) {
            Outcome o = assertLike(plain, c);
            assertTrue(o.text().contains("threw java.lang.IllegalStateException: gave up"), c + ": " + o.text());
            assertEquals(plain.result.first().failure().lines().findFirst(), o.result.first().failure().lines().findFirst(), c);
        }
    }

    @Test
    void whatTheControllerThrewIsToldWithoutAskingTheExceptionAgainOnTheSimulatorsThreads() {
        Outcome plain = run("Quits");
        Outcome o = assertLike(plain, "QuitsOddly");
        assertEquals("QuitsOddly$Odd: gave up", o.result.first().failure(), o.text());
        assertTrue(o.text().startsWith("threw C$Odd: gave up; the robot was stopped.\nC$Odd: gave up\n\tat C.run(C.java:"), o.text());
    }

    @Test
    void aHungControllerIsStoppedWithoutCallingItsInterrupt() {
        Outcome plain = run("Hangs");
        assertEquals(ControllerStatus.HUNG, plain.result.first().status(), plain.text());
        for (String c : List.of("HangsInterruptSpins", "HangsInterruptThrows", "HangsInterruptedSpins")) {
            assertLike(plain, c);
        }
    }

    @Test
    void threadsItStartsBehaveTheSameWhenTheirClassesOverrideThreadsMethods() {
        Outcome plain = run("Crew");
        assertEquals(List.of("main current true state RUNNABLE", "helper before start: alive false state NEW",
                "helper current true alive true state RUNNABLE interrupted true", "helper interrupted after 1, flag false",
                "helper current true alive true state RUNNABLE interrupted false",
                "helper started: alive true state TIMED_WAITING", "helper interrupted after 68, flag false",
                "helper joined: alive false state TERMINATED seen 68", "main saw its own interrupt, flag false"),
                plain.console, plain.text());
        Outcome o = assertLike(plain, "CrewOverriding");
        assertEquals(plain.console, o.console);
    }
}
