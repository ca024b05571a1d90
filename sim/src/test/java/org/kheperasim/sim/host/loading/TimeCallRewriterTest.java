package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.SimClock;
import org.kheperasim.sim.host.SimClockTestHooks;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

class TimeCallRewriterTest {
    private static final String CHECKPOINT = "org/kheperasim/sim/host/SimClock.checkpoint()V";
    private static final HierarchyLookup NOT_THREAD = (owner, name, descriptor) -> false;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();

    @BeforeEach
    void bindClock() {
        SimClock.bind(clock);
    }

    @AfterEach
    void unbindClock() {
        SimClock.unbind();
    }

    private byte[] compile(String className, String source) throws IOException {
        JavaSources.compile(dir, Map.of(className, source));
        return Files.readAllBytes(dir.resolve(className + ".class"));
    }

    /** @return each call in {@code method} of the class file, as owner.name descriptor */
    private static List<String> calls(byte[] classFile, String method) {
        List<String> calls = new ArrayList<>();
        new ClassReader(classFile).accept(new ClassVisitor(Opcodes.ASM9) {
            @Override
            public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                    String[] exceptions) {
                return !name.equals(method) ? null : new MethodVisitor(Opcodes.ASM9) {
                    @Override
                    public void visitMethodInsn(int opcode, String owner, String called, String calledDescriptor,
                            boolean isInterface) {
                        calls.add(owner + "." + called + calledDescriptor);
                    }
                };
            }
        }, 0);
        return calls;
    }

    /** A Java 17 class with one static method, written directly in bytecode. */
    private static byte[] generate(String className, String method, String descriptor, Consumer<MethodVisitor> body) {
        ClassWriter writer = new ClassWriter(ClassWriter.COMPUTE_FRAMES);
        writer.visit(Opcodes.V17, Opcodes.ACC_PUBLIC | Opcodes.ACC_SUPER, className, null, "java/lang/Object", null);
        MethodVisitor mv = writer.visitMethod(Opcodes.ACC_PUBLIC | Opcodes.ACC_STATIC, method, descriptor, null, null);
        mv.visitCode();
        body.accept(mv);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
        writer.visitEnd();
        return writer.toByteArray();
    }

    /** Load a generated class through a controller class loader, so it is rewritten and verified. */
    private Method load(String className, byte[] classFile, String method, Class<?>... parameters) throws Exception {
        Path classes = Files.createDirectories(dir.resolve("generated"));
        Files.write(classes.resolve(className + ".class"), classFile);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(classes), getClass().getClassLoader())) {
            return loader.loadClass(className).getMethod(method, parameters);
        }
    }

    @Test
    void aClassWithNothingToRewriteIsReturnedAsIs() throws Exception {
        byte[] classFile = compile("Plain", """
                public class Plain extends Thread {
                    int twice(int x) { return x > 0 ? 2 * x : 0; }
                }
                """);

        assertSame(classFile, TimeCallRewriter.rewrite(classFile, NOT_THREAD));
    }

    @Test
    void aStaticCallThroughAnotherClassIsRewrittenOnlyWhenTheLookupSaysItReachesThread() throws Exception {
        byte[] classFile = compile("Robot", """
                public class Robot extends Thread {
                    @Override public void run() {
                        try { sleep(100); Thread.sleep(5); } catch (InterruptedException e) { }
                    }
                }
                """);
        List<String> asked = new ArrayList<>();

        byte[] kept = TimeCallRewriter.rewrite(classFile, (owner, name, descriptor) -> {
            asked.add(owner + "." + name + descriptor);
            return false;
        });
        byte[] redirected = TimeCallRewriter.rewrite(classFile, (owner, name, descriptor) -> true);

        assertEquals(List.of("Robot.sleep(J)V"), asked, "Thread's own call needs no lookup");
        assertEquals(List.of("Robot.sleep(J)V", "org/kheperasim/sim/host/SimClock.sleep(J)V"), calls(kept, "run"));
        assertEquals(List.of("org/kheperasim/sim/host/SimClock.sleep(J)V", "org/kheperasim/sim/host/SimClock.sleep(J)V"),
                calls(redirected, "run"));
    }

    @Test
    void everyLoopGetsOneCheckpointAndStraightCodeNone() throws Exception {
        byte[] classFile = compile("Loops", """
                public class Loops {
                    static int loops(int n) {
                        int sum = 0;
                        for (int i = 0; i < n; i++) {
                            int j = 0;
                            do { sum += j; } while (++j < i);
                        }
                        while (true) {
                            if (sum > 100) break;
                            sum++;
                        }
                        for (int k : new int[] {1, 2}) { sum += k; }
                        return sum;
                    }
                    static int straight(int n) {
                        if (n > 3) { n = 3; }
                        switch (n) { case 1: return 10; case 2: return 20; default: return n > 0 ? n : -n; }
                    }
                }
                """);

        byte[] rewritten = TimeCallRewriter.rewrite(classFile, NOT_THREAD);

        assertEquals(4, calls(rewritten, "loops").stream().filter(CHECKPOINT::equals).count());
        assertEquals(List.of(), calls(rewritten, "straight"));
    }

    @Test
    void aSwitchThatJumpsBackGetsACheckpointAndStaysVerifiable() throws Exception {
        byte[] classFile = generate("SwitchLoop", "spin", "(I)V", mv -> {
            Label top = new Label();
            Label next = new Label();
            Label end = new Label();
            mv.visitLabel(top);
            mv.visitVarInsn(Opcodes.ILOAD, 0);
            mv.visitTableSwitchInsn(0, 1, next, top, next);
            mv.visitLabel(next);
            mv.visitVarInsn(Opcodes.ILOAD, 0);
            mv.visitLookupSwitchInsn(end, new int[] {3}, new Label[] {top});
            mv.visitLabel(end);
            mv.visitInsn(Opcodes.RETURN);
        });
        assertEquals(List.of(CHECKPOINT, CHECKPOINT), calls(TimeCallRewriter.rewrite(classFile, NOT_THREAD), "spin"));
        Method spin = load("SwitchLoop", classFile, "spin", int.class);

        spin.invoke(null, 7);
        clock.requestStop();
        SimClockTestHooks.stopRequested();
        try {
            for (int loopingArgument : new int[] {0, 3}) {
                InvocationTargetException e = assertThrows(InvocationTargetException.class,
                        () -> spin.invoke(null, loopingArgument));
                assertTrue(e.getCause() instanceof FakeClock.Stop, e.getCause().toString());
            }
        } finally {
            SimClockTestHooks.stopSettled();
        }
    }

    @Test
    void sleepWithADurationSleepsOnTheSimulatedClock() throws Exception {
        byte[] classFile = generate("DurationNap", "nap", "()V", mv -> {
            mv.visitLdcInsn(7L);
            mv.visitMethodInsn(Opcodes.INVOKESTATIC, "java/time/Duration", "ofMillis", "(J)Ljava/time/Duration;", false);
            mv.visitMethodInsn(Opcodes.INVOKESTATIC, "java/lang/Thread", "sleep", "(Ljava/time/Duration;)V", false);
            mv.visitInsn(Opcodes.RETURN);
        });

        load("DurationNap", classFile, "nap").invoke(null);

        assertEquals(List.of(7_000_000L), clock.sleeps());
    }

    @Test
    void aClassFileTooNewIsRejectedWithTheFix() throws Exception {
        byte[] classFile = compile("Newer", "public class Newer { }");
        classFile[7] = (byte) 200;

        UnsupportedClassVersionError e = assertThrows(UnsupportedClassVersionError.class,
                () -> TimeCallRewriter.rewrite(classFile, NOT_THREAD));

        assertTrue(e.getMessage().contains("Java 156") && e.getMessage().contains("--release 17"), e.getMessage());
    }

    @Test
    void bytesThatAreNoClassFileAreRejected() {
        assertThrows(ClassFormatError.class, () -> TimeCallRewriter.rewrite(new byte[] {1, 2, 3}, NOT_THREAD));
        assertThrows(ClassFormatError.class, () -> TimeCallRewriter.rewrite(
                new byte[] {(byte) 0xCA, (byte) 0xFE, (byte) 0xBA, (byte) 0xBE, 0, 0, 0, 61, 0, 9}, NOT_THREAD));
    }
}
