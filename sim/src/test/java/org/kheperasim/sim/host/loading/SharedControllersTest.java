package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * A stateless controller's classes are defined once for every robot of every run (the JIT compiles
 * them once); one that keeps state in static fields keeps classes of its own for each robot, so its
 * statics stay each robot's own; a recompiled class is picked up.
 */
class SharedControllersTest {
    @TempDir
    Path dir;

    @Test
    void everyBundledControllerIsSharedAcrossRobotsAndRuns() {
        for (String name : ControllerCatalog.bundled()) {
            Class<?> first = new ControllerCatalog(List.of()).load(name);
            Class<?> again = new ControllerCatalog(List.of()).load(name);
            assertNull(SharedControllers.whyNotShared(first), name);
            assertSame(first, again, name + ": one definition for every run");
        }
    }

    private Path compile(Map<String, String> sources) throws Exception {
        Path src = Files.createDirectories(dir.resolve("src" + System.nanoTime()));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new java.util.ArrayList<>(List.of("-cp", System.getProperty("java.class.path"), "-d",
                classes.toString(), "--release", "17", "-proc:none"));
        for (Map.Entry<String, String> e : sources.entrySet()) {
            Path f = src.resolve(e.getKey() + ".java");
            Files.writeString(f, e.getValue());
            args.add(f.toString());
        }
        assertEquals(0, javax.tools.ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(new String[0])));
        return classes;
    }

    private static final String HEADER = "import org.kheperasim.api.*;\n";

    @Test
    void whatKeepsStateIsNotShared() throws Exception {
        Map<String, String> cases = Map.of(
                "Counter", "public class Counter extends StepController { static int steps;"
                        + " protected void step() { steps++; setSpeeds(1, 1); } }",
                "Tuned", "public class Tuned extends StepController { static final int[] W = {1, 2};"
                        + " protected void step() { W[0]++; setSpeeds(W[0], W[1]); } }",
                "Handed", "public class Handed extends StepController { static final int[] W = {1, 2};"
                        + " protected void step() { java.util.Arrays.fill(W, 3); setSpeeds(1, 1); } }",
                "Listed", "public class Listed extends StepController { static final java.util.List<Integer> L ="
                        + " new java.util.ArrayList<>(); protected void step() { L.add(1); setSpeeds(1, 1); } }",
                "Weights", "public class Weights extends StepController { static final double[][] W = {{0.5, 1}, {1, 0.5}};"
                        + " protected void step() { setSpeeds((int) (W[0][1] * W.length), (int) W[1][0]); } }");
        Path classes = compile(Map.of("Counter", HEADER + cases.get("Counter"), "Tuned", HEADER + cases.get("Tuned"),
                "Handed", HEADER + cases.get("Handed"), "Listed", HEADER + cases.get("Listed"),
                "Weights", HEADER + cases.get("Weights")));
        for (String kept : List.of("Counter", "Tuned", "Handed", "Listed")) {
            Class<?> a = new ControllerCatalog(List.of(classes)).load(kept);
            Class<?> b = new ControllerCatalog(List.of(classes)).load(kept);
            assertNotSame(a, b, kept + " keeps state: a class of its own each time");
            assertTrue(SharedControllers.whyNotShared(a) != null, kept);
        }
        Class<?> a = new ControllerCatalog(List.of(classes)).load("Weights");
        assertSame(a, new ControllerCatalog(List.of(classes)).load("Weights"), "read-only constant arrays are shared");
    }

    @Test
    void aStaticCounterStaysEachRobotsOwn() throws Exception {
        Path classes = compile(Map.of("Counter", HEADER + "public class Counter extends StepController { static int steps;"
                + " protected void step() { steps++; setSpeeds(steps % 5, 1); } }"));
        RunResult r = Simulation.builder().arena(org.kheperasim.sim.arena.ArenaFormat.parse(
                "khepera-arena 1\nname two\nsize 1219.2 1219.2\nrobot 300 300 0\nrobot 900 900 180\n", "two.arena"))
                .classpath(List.of(classes)).controller("Counter").seed(1).seconds(2).run();
        // Each robot counts its own steps, so both turn the same way; a shared counter would count twice as fast.
        assertEquals(r.robots().get(0).distanceMm(), r.robots().get(1).distanceMm(), 1.0, r.robots().toString());
    }

    @Test
    void aRecompiledControllerIsPickedUp() throws Exception {
        Path classes = compile(Map.of("Speedy", HEADER + "public class Speedy extends StepController {"
                + " protected void step() { setSpeeds(2, 2); } }"));
        Class<?> first = new ControllerCatalog(List.of(classes)).load("Speedy");
        assertSame(first, new ControllerCatalog(List.of(classes)).load("Speedy"));
        compile(Map.of("Speedy", HEADER + "public class Speedy extends StepController {"
                + " protected void step() { setSpeeds(5, 5); } }"));
        assertNotSame(first, new ControllerCatalog(List.of(classes)).load("Speedy"), "the new class file is loaded");
    }
}
