package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * Issue 35, item 2: no robot can stall another through a JVM-wide object's monitor. An interned
 * string literal, the API's {@code Class} objects and a boxed value from the JVM's cache are one
 * object for every robot; each robot's code locks (waits on, notifies) a monitor of its own for
 * them, so one robot that holds {@code "khepera"} or {@code IrSensor.class} while it sleeps does not
 * stop the other, and an honest swarm that guards its motor update with {@code "swarm-lock"} drives
 * every robot. Within one robot the lock still excludes its own threads.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotMonitorsTest {
    /** Two robots well apart, facing open floor. */
    private static final Arena TWO = ArenaFormat.parse("""
            khepera-arena 1
            name two
            size 1219.2 1219.2
            wall 0 4 1219.2 4 8
            wall 0 1215.2 1219.2 1215.2 8
            wall 4 0 4 1219.2 8
            wall 1215.2 0 1215.2 1219.2 8
            robot 300 300 0
            robot 300 900 0
            """, "two.arena");

    @TempDir
    static Path dir;
    static Path classes;

    private static final Map<String, String> SOURCES = new LinkedHashMap<>();

    static {
        // Holds a JVM-wide object's monitor while it sleeps, for good.
        SOURCES.put("LiteralHog", "synchronized (\"khepera\") { sleepMillis(600_000); }");
        SOURCES.put("ClassHog", "synchronized (IrSensor.class) { sleepMillis(600_000); }");
        SOURCES.put("BoxHog", "synchronized (Integer.valueOf(7)) { sleepMillis(600_000); }");
        // Lock the same objects around each motor update.
        SOURCES.put("LiteralDriver", "synchronized (\"khepera\") { setSpeeds(4, 4); } sleepMillis(20);");
        SOURCES.put("ClassDriver", "synchronized (IrSensor.class) { setSpeeds(4, 4); } sleepMillis(20);");
        SOURCES.put("BoxDriver", "synchronized (Integer.valueOf(7)) { setSpeeds(4, 4); } sleepMillis(20);");
        // The honest swarm: its motor update guarded by a literal, the lock held across a sleep now and then.
        SOURCES.put("SwarmLock", "synchronized (\"swarm-lock\") { setSpeeds(4, 4); sleepMillis(5); } sleepMillis(20);");
    }

    /**
     * Two threads of one robot take turns in a block on a literal (another's lock: a stand-in), each
     * sleeping inside it; a third waits on the literal until the first notifies it. Prints how often
     * two were inside at once, and what the waiter saw.
     */
    private static final String EXCLUSIVE = """
            import org.kheperasim.api.*;

            public class Exclusive extends Controller {
                private int inside;
                private int overlaps;
                private int entries;
                private boolean ready;
                private String waiter = "never woke";

                private void take(Object lock) {
                    for (int i = 0; i < 15; i++) {
                        synchronized (lock) {
                            inside++;
                            entries++;
                            if (inside > 1) {
                                overlaps++;
                            }
                            if (!Thread.holdsLock(lock)) {
                                overlaps += 1000;
                            }
                            sleepMillis(7);
                            inside--;
                        }
                        sleepMillis(1);
                    }
                }

                @Override
                protected void doWork() {
                    Thread w = new Thread(() -> {
                        synchronized ("swarm-lock") {
                            while (!ready) {
                                try {
                                    "swarm-lock".wait(1000);
                                } catch (InterruptedException e) {
                                    return;
                                }
                            }
                            waiter = "woke holding " + Thread.holdsLock("swarm-lock");
                        }
                    });
                    w.start();
                    Thread other = new Thread(() -> take("swarm-lock"));
                    other.start();
                    take("swarm-lock");
                    try {
                        other.join();
                        Thread third = new Thread(() -> take(IrSensor.class));
                        third.start();
                        take(IrSensor.class);
                        third.join();
                        synchronized ("swarm-lock") {
                            ready = true;
                            "swarm-lock".notifyAll();
                        }
                        w.join();
                    } catch (InterruptedException e) {
                        return;
                    }
                    print("exclusive entries " + entries + " overlaps " + overlaps + " waiter " + waiter);
                    sleepMillis(600_000);
                }
            }
            """;

    @BeforeAll
    static void compile() throws Exception {
        Path src = Files.createDirectories(dir.resolve("src"));
        List<String> files = new ArrayList<>();
        for (Map.Entry<String, String> s : SOURCES.entrySet()) {
            Path f = src.resolve(s.getKey() + ".java");
            Files.writeString(f, "import org.kheperasim.api.*;\n\npublic class " + s.getKey() + " extends Controller {\n"
                    + "    @Override\n    protected void doWork() {\n        " + s.getValue() + "\n    }\n}\n");
            files.add(f.toString());
        }
        Path exclusive = src.resolve("Exclusive.java");
        Files.writeString(exclusive, EXCLUSIVE);
        files.add(exclusive.toString());
        classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d", classes.toString(),
                "-g", "--release", "17", "-proc:none"));
        args.addAll(files);
        assertEquals(0, javax.tools.ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])));
    }

    private record Outcome(RunResult result, List<String> console) {
        RunResult.RobotResult robot(int i) {
            return result.robots().get(i);
        }

        String text() {
            return result.robots() + "\n" + String.join("\n", console);
        }
    }

    private static Outcome run(String first, String second, double seconds) {
        List<String> console = new ArrayList<>();
        RunResult r = Simulation.builder().arena(TWO).classpath(List.of(classes)).controller(first).robot(1, second, null)
                .seed(1).seconds(seconds).console((ConsoleLine line) -> {
                    synchronized (console) {
                        console.add(line.text());
                    }
                }).run();
        return new Outcome(r, console);
    }

    /** The second robot drove all the run (4 mm/s-ish for 3 s), neither robot was hung. */
    private static void assertDrove(Outcome o, int robot) {
        assertTrue(o.robot(robot).distanceMm() > 50, "robot " + robot + " drove: " + o.text());
        assertTrue(o.robot(robot).status() != ControllerStatus.HUNG && o.robot(robot).status() != ControllerStatus.FAILED,
                "robot " + robot + " ran: " + o.text());
    }

    @Test
    void aRobotHoldingALiteralsMonitorWhileItSleepsDoesNotStopAnother() {
        Outcome o = run("LiteralHog", "LiteralDriver", 3);
        assertDrove(o, 1);
        assertTrue(o.robot(0).status() != ControllerStatus.HUNG, "the sleeper only sleeps: " + o.text());
    }

    @Test
    void aRobotHoldingTheApisClassMonitorWhileItSleepsDoesNotStopAnother() {
        assertDrove(run("ClassHog", "ClassDriver", 3), 1);
    }

    @Test
    void aRobotHoldingACachedBoxsMonitorWhileItSleepsDoesNotStopAnother() {
        assertDrove(run("BoxHog", "BoxDriver", 3), 1);
    }

    @Test
    void anHonestSwarmThatLocksALiteralDrivesEveryRobot() {
        Outcome o = run("SwarmLock", "SwarmLock", 3);
        assertDrove(o, 0);
        assertDrove(o, 1);
    }

    @Test
    void withinOneRobotTheLockStillExcludesItsOwnThreadsAndWaitAndNotifyMeetOnIt() {
        Outcome o = run("Exclusive", "LiteralHog", 5);
        String line = o.console().stream().filter(l -> l.contains("exclusive entries")).findFirst().orElse("none");
        assertTrue(line.endsWith("exclusive entries 60 overlaps 0 waiter woke holding true"), o.text());
    }
}
