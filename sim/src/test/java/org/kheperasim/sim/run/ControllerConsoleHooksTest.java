package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * What course code prints about its errors reaches the run's console, stamped with simulated time,
 * and not the JVM's own error stream: {@code e.printStackTrace()}, and the logger NetBeans writes
 * into generated catch blocks ({@code Logger.getLogger(...).log(Level.SEVERE, null, ex)}), which is
 * the controller's own, not one the whole JVM shares.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ControllerConsoleHooksTest {
    @TempDir
    Path dir;

    @Test
    void stackTracesAndLogRecordsGoToTheRunsConsole() throws IOException {
        Path src = dir.resolve("LogBot.java");
        Files.writeString(src, """
                import edu.wsu.KheperaSimulator.RobotController;
                import java.util.logging.Level;
                import java.util.logging.Logger;

                public class LogBot extends RobotController {
                    private int calls;

                    public void doWork() throws Exception {
                        if (calls++ == 0) {
                            try {
                                throw new IllegalStateException("boom");
                            } catch (IllegalStateException ex) {
                                Logger.getLogger(LogBot.class.getName()).log(Level.SEVERE, null, ex);
                                Logger.getLogger(LogBot.class.getName()).fine("not shown: below INFO");
                                ex.printStackTrace();
                            }
                        }
                        sleep(100);
                    }

                    public void close() throws Exception {
                    }
                }
                """);
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", classes.toString(), "-g", "--release", "17", src.toString()));
        List<ConsoleLine> console = new CopyOnWriteArrayList<>();
        PrintStream realErr = System.err;
        ByteArrayOutputStream leaked = new ByteArrayOutputStream();
        RunResult r;
        System.setErr(new PrintStream(leaked, true, StandardCharsets.UTF_8));
        try {
            r = Simulation.builder().arena("lab").classpath(List.of(classes)).controller("LogBot").seed(1).seconds(1)
                    .console(console::add).run();
        } finally {
            System.setErr(realErr);
        }

        assertEquals(ControllerStatus.STOPPED, r.first().status());
        List<String> errors = console.stream().filter(l -> l.kind() == ConsoleLine.Kind.ERROR).map(ConsoleLine::text).toList();
        assertEquals("SEVERE: null", errors.get(0), errors.toString());
        assertEquals("java.lang.IllegalStateException: boom", errors.get(1), errors.toString());
        assertTrue(errors.get(2).contains("at LogBot.doWork(LogBot.java:11)"), errors.toString());
        assertTrue(errors.stream().filter(l -> l.equals("java.lang.IllegalStateException: boom")).count() == 2,
                "the logger's trace, then printStackTrace's: " + errors);
        assertTrue(errors.stream().noneMatch(l -> l.contains("not shown")), errors.toString());
        assertEquals("", leaked.toString(StandardCharsets.UTF_8), "nothing went to the JVM's own error stream");
    }
}
