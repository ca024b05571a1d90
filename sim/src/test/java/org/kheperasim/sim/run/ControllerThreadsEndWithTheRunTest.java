package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every thread a controller's code causes is the run's. A pool, an asynchronous future, the common
 * fork-join pool, a Timer, a Cleaner and a finalizer would run the controller's code on threads the
 * JDK starts itself, outside the lockstep (in real time, in any order, and after the run): each is
 * refused when the controller is loaded. A parallel stream runs on the controller's own thread, in
 * the lockstep. Each controller below runs in a JVM of its own, as {@code run} does, and that JVM
 * ends by itself after the run, whatever its threads tried to do.
 */
@Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ControllerThreadsEndWithTheRunTest {
    @TempDir
    static Path dir;
    static Path classes;

    private static final String SPIN = "() -> { long n = 0; while (n >= 0) { n++; } }";

    /** Name, the body of doWork(), the exit status and what the output must say. */
    private static final String[][] CONTROLLERS = {
        {"PoolSpinner", "java.util.concurrent.Executors.newFixedThreadPool(2).execute(" + SPIN + ");", "2",
            "uses java.util.concurrent.Executors.newFixedThreadPool(int): thread pools run tasks on threads the JDK starts"},
        {"AsyncSpinner", "java.util.concurrent.CompletableFuture.runAsync(" + SPIN + ");", "2",
            "uses java.util.concurrent.CompletableFuture.runAsync(Runnable): thread pools run tasks"},
        {"CommonPoolSpinner", "java.util.concurrent.ForkJoinPool.commonPool().execute(" + SPIN + ");", "2",
            "uses java.util.concurrent.ForkJoinPool.commonPool(): thread pools run tasks"},
        {"TimerSpinner", "new java.util.Timer().schedule(new java.util.TimerTask() { public void run() { long n = 0;"
            + " while (n >= 0) { n++; } } }, 0);", "2", "uses java.util.Timer: a Timer runs its tasks on a thread of its own"},
        {"CleanerSpinner", "java.lang.ref.Cleaner.create().register(this, " + SPIN + ");", "2",
            "uses java.lang.ref.Cleaner.create(): a Cleaner and reference queues run code on a thread of the JDK"},
        {"ParallelSpinner", "java.util.stream.IntStream.range(0, 4).parallel().forEach(i -> { long n = 0; while (n >= 0) { n++; } });",
            "1", "hung"},
        {"ParallelStreamSpinner", "java.util.List.of(1, 2, 3).parallelStream().forEach(i -> { long n = 0; while (n >= 0) { n++; } });",
            "1", "hung"},
        {"ParallelWorker", "java.util.Set<Thread> seen = java.util.concurrent.ConcurrentHashMap.newKeySet();\n"
            + "long sum = java.util.stream.LongStream.range(0, 100_000).parallel().peek(i -> seen.add(Thread.currentThread())).sum();\n"
            + "java.util.List.of(1, 2, 3).parallelStream().forEach(i -> seen.add(Thread.currentThread()));\n"
            + "System.out.println(\"sum \" + sum + \" on \" + seen.size() + \" thread, the controller's: \" + seen.contains(this));\n"
            + "sleepMillis(1000);", "0", "sum 4999950000 on 1 thread, the controller's: true"},
    };

    @BeforeAll
    static void compile() throws IOException {
        classes = Files.createDirectories(dir.resolve("classes"));
        List<String> files = new ArrayList<>();
        for (String[] c : CONTROLLERS) {
            files.add(write(c[0], "import org.kheperasim.api.*;\n\npublic class " + c[0] + " extends Controller {\n"
                    + "    @Override\n    protected void doWork() {\n        " + c[1].replace("\n", "\n        ")
                    + "\n        sleepMillis(100);\n    }\n}\n"));
        }
        files.add(write("Finalized", """
                import org.kheperasim.api.*;

                public class Finalized extends Controller {
                    @Override
                    protected void finalize() {
                        long n = 0;
                        while (n >= 0) {
                            n++;
                        }
                    }

                    @Override
                    protected void doWork() {
                        new Finalized();
                        System.gc();
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

    /** Run a controller for 3 simulated seconds in a JVM of its own; @return its exit status and output */
    private static String[] runAlone(String controller) throws Exception {
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "run", "--arena", "lab", "--classpath",
                classes.toString(), "--controller", controller, "--seconds", "3", "--hang-timeout", "2")
                .redirectErrorStream(true).start();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        Thread reader = new Thread(() -> {
            try {
                p.getInputStream().transferTo(out);
            } catch (IOException e) {
                // the process ended
            }
        });
        reader.start();
        boolean ended = p.waitFor(180, TimeUnit.SECONDS); // generous on a busy machine; without the change: never
        if (!ended) {
            p.destroyForcibly().waitFor();
        }
        reader.join(10_000);
        String text = out.toString(StandardCharsets.UTF_8);
        assertTrue(ended, controller + ": the JVM did not end by itself after its run: " + text);
        return new String[] {String.valueOf(p.exitValue()), text};
    }

    /**
     * The JVMs are independent (one controller each), and most of each is a JVM starting or a hang timeout running out:
     * two at a time, each checked as it was alone.
     */
    @Test
    void eachJvmEndsByItselfAfterTheRunAndSaysWhy() throws Exception {
        ExecutorService two = Executors.newFixedThreadPool(2);
        try {
            List<Future<String[]>> runs = new ArrayList<>();
            for (String[] c : CONTROLLERS) {
                runs.add(two.submit(() -> runAlone(c[0])));
            }
            Future<String[]> finalized = two.submit(() -> runAlone("Finalized"));
            for (int i = 0; i < CONTROLLERS.length; i++) {
                String[] c = CONTROLLERS[i];
                String[] r = result(runs.get(i));
                assertEquals(c[2], r[0], c[0] + " exit status: " + r[1]);
                assertTrue(r[1].contains(c[3]), c[0] + " says '" + c[3] + "': " + r[1]);
            }
            String[] r = result(finalized);
            assertEquals("2", r[0], r[1]);
            assertTrue(r[1].contains("Finalized.java:6: declares finalize(): a finalizer runs on the JVM's finalizer thread"), r[1]);
        } finally {
            two.shutdownNow();
        }
    }

    /** @return what {@link #runAlone} returned; what it threw (a failed assertion) as it threw it */
    private static String[] result(Future<String[]> run) throws Exception {
        try {
            return run.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw (Exception) e.getCause();
        }
    }
}
