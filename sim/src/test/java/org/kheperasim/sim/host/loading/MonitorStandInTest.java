package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.IrSensor;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * The loader-level half of issue 35's item 2: what each controller loader's code locks for an
 * object it does not own (a stand-in of its own, one per object), what it locks for its own
 * objects (themselves), and the shape of the rewrite (javac's blocks keep balanced monitors, so
 * the JIT still compiles them).
 */
class MonitorStandInTest {
    @TempDir
    Path dir;

    private static final String LOCKER = """
            package bot;
            public class Locker {
                private final Object lock = new Object();
                int n;
                public void both() {
                    synchronized ("swarm-lock") {
                        n++;
                    }
                    synchronized (lock) {
                        n++;
                    }
                    synchronized (this) {
                        n++;
                    }
                }
            }
            """;

    private ControllerClassLoader loader(Path classes) {
        return new ControllerClassLoader(List.of(classes), getClass().getClassLoader());
    }

    @Test
    void eachLoaderHasItsOwnStandInForAJvmWideObjectAndKeepsItsOwnObjects() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("c")), Map.of("bot.Locker", LOCKER));
        try (ControllerClassLoader one = loader(classes); ControllerClassLoader two = loader(classes)) {
            Class<?> mine = one.loadClass("bot.Locker");
            Object literal = "swarm-lock";
            Object a = MonitorHooks.own(literal, mine);
            assertNotSame(literal, a, "a literal is every robot's: the robot locks a stand-in");
            assertSame(a, MonitorHooks.own(literal, mine), "the same stand-in each time, for every thread of the robot");
            assertSame(a, MonitorHooks.own(a, mine), "a robot's stand-in is its own");
            Object b = MonitorHooks.own(literal, two.loadClass("bot.Locker"));
            assertNotSame(a, b, "another robot's loader: another stand-in");
            assertNotSame(IrSensor.class, MonitorHooks.own(IrSensor.class, mine));
            assertNotSame(Integer.valueOf(7), MonitorHooks.own(Integer.valueOf(7), mine));
            Object own = mine.getConstructor().newInstance();
            assertSame(own, MonitorHooks.own(own, mine), "an object of the controller's own class keeps its monitor");
            assertSame(mine, MonitorHooks.own(mine, mine), "so does its own class");
            assertEquals("java.lang.String", MonitorHooks.typeName(a), "messages name what was locked");
        }
    }

    @Test
    void standInsOfObjectsThatAreGoneAreDropped() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("c")), Map.of("bot.Locker", LOCKER));
        try (ControllerClassLoader one = loader(classes)) {
            Class<?> mine = one.loadClass("bot.Locker");
            for (int i = 0; i < 10_000; i++) {
                MonitorHooks.own(new Object(), mine);
            }
            for (int i = 0; i < 50 && one.monitors().size() > 1_000; i++) {
                System.gc();
                Thread.sleep(20);
            }
            assertTrue(one.monitors().size() < 1_000, "a lock per step leaves no trail: " + one.monitors().size());
        }
    }

    @Test
    void javacsBlocksGetTheStandInOnceAndLeaveTheMonitorTheyEntered() throws Exception {
        Path classes = JavaSources.compile(Files.createDirectories(dir.resolve("c")), Map.of("bot.Locker", LOCKER));
        byte[] rewritten = TimeCallRewriter.rewrite(Files.readAllBytes(classes.resolve("bot/Locker.class")),
                (owner, name, descriptor) -> false, true);
        List<String> calls = new ArrayList<>();
        new ClassReader(rewritten).accept(new ClassVisitor(Opcodes.ASM9) {
            @Override
            public MethodVisitor visitMethod(int access, String name, String descriptor, String signature, String[] ex) {
                if (!name.equals("both")) {
                    return null;
                }
                return new MethodVisitor(Opcodes.ASM9) {
                    @Override
                    public void visitMethodInsn(int opcode, String owner, String n, String d, boolean itf) {
                        if (owner.endsWith("MonitorHooks") || owner.endsWith("ThreadHooks")) {
                            calls.add(n);
                        }
                    }

                    @Override
                    public void visitInsn(int opcode) {
                        if (opcode == Opcodes.MONITORENTER || opcode == Opcodes.MONITOREXIT) {
                            calls.add(opcode == Opcodes.MONITORENTER ? "ENTER" : "EXIT");
                        }
                    }
                };
            }
        }, 0);
        // Three blocks, each left twice (normally and on the way out of an exception): one look-up each, at entry.
        assertEquals(3, calls.stream().filter("own"::equals).count(), calls.toString());
        assertEquals(3, calls.stream().filter("ENTER"::equals).count(), calls.toString());
        assertEquals(6, calls.stream().filter("EXIT"::equals).count(), calls.toString());
        assertEquals(List.of("own", "monitorEnter", "ENTER"), calls.subList(0, 3), calls.toString());
    }
}
