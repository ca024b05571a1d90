package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.SimClock;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * The newest class file a controller may be compiled to (docs/simulation-model.md): what both the
 * time-call rewriter (ASM, up to Java 25, class file version 69) and the running JVM read. A class
 * of exactly that version loads through {@link ControllerClassLoader} with its sleeps rewritten; one
 * version newer is refused with the fix.
 */
class ClassFileVersionTest {
    /** The rewriter's own limit: Java 25. */
    static final int REWRITER_NEWEST = 69;
    /** The newest version accepted on this JVM. */
    static final int NEWEST = Math.min(REWRITER_NEWEST, 44 + Runtime.version().feature());

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

    /** A public class {@code name} of that class-file version with {@code public static void nap()} calling {@code Thread.sleep(5)}. */
    private Path classFile(String name, int version) throws IOException {
        ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
        w.visit(version, Opcodes.ACC_PUBLIC | Opcodes.ACC_SUPER, name, null, "java/lang/Object", null);
        MethodVisitor nap = w.visitMethod(Opcodes.ACC_PUBLIC | Opcodes.ACC_STATIC, "nap", "()V", null,
                new String[] {"java/lang/InterruptedException"});
        nap.visitCode();
        nap.visitLdcInsn(5L);
        nap.visitMethodInsn(Opcodes.INVOKESTATIC, "java/lang/Thread", "sleep", "(J)V", false);
        nap.visitInsn(Opcodes.RETURN);
        nap.visitMaxs(0, 0);
        nap.visitEnd();
        w.visitEnd();
        Path file = dir.resolve(name + ".class");
        Files.write(file, w.toByteArray());
        return file;
    }

    @Test
    void asmReadsEveryVersionTheSimulatorAccepts() throws IOException {
        new ClassReader(Files.readAllBytes(classFile("Newest", REWRITER_NEWEST))); // no exception from ASM itself
    }

    @Test
    void aClassOfTheNewestAcceptedVersionLoadsAndIsRewritten() throws Exception {
        classFile("Newest", NEWEST);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(dir), getClass().getClassLoader())) {
            Class<?> type = loader.loadClass("Newest");
            type.getMethod("nap").invoke(null);
        }
        assertEquals(List.of(5_000_000L), clock.sleeps(), "Thread.sleep(5) slept 5 ms of simulated time");
    }

    @Test
    void aClassOneVersionNewerIsRefusedWithTheFix() throws Exception {
        Path file = classFile("TooNew", NEWEST + 1);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(dir), getClass().getClassLoader())) {
            UnsupportedClassVersionError e = assertThrows(UnsupportedClassVersionError.class,
                    () -> loader.loadClass("TooNew"));
            String m = e.getMessage();
            assertTrue(m.contains("TooNew") && m.contains(file.toString()), m);
            assertTrue(m.startsWith(file + ": compiled for Java " + (NEWEST + 1 - 44) + " (class file version "
                    + (NEWEST + 1) + "), newer than "), m);
            assertTrue(m.contains("Java " + (NEWEST - 44)) && m.endsWith("; compile it with `--release 17`"), m);
        }
    }

    /** Issue 35, item 8: a class file cut short is refused naming the file, as a ClassFormatError (no ASM exception). */
    @Test
    void aMalformedClassFileIsRefusedNamingItsFile() throws Exception {
        Path file = classFile("Cut", NEWEST);
        byte[] whole = Files.readAllBytes(file);
        Files.write(file, java.util.Arrays.copyOf(whole, whole.length / 2));
        for (boolean contained : new boolean[] {true, false}) {
            try (ControllerClassLoader loader = new ControllerClassLoader(List.of(dir), getClass().getClassLoader(), contained)) {
                ClassFormatError e = assertThrows(ClassFormatError.class, () -> loader.loadClass("Cut"));
                assertTrue(e.getMessage().startsWith(file + ": not a well-formed class file ("), e.getMessage());
            }
        }
    }

    /** Issue 35, item 8: a 3 GB (sparse) class file is refused by its size, before anything is read. */
    @Test
    void aHugeClassFileIsRefusedByItsSizeUnread() throws Exception {
        Path file = dir.resolve("Big.class");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(file.toFile(), "rw")) {
            f.setLength(3L << 30);
        }
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(dir), getClass().getClassLoader())) {
            ClassFormatError e = assertThrows(ClassFormatError.class, () -> loader.loadClass("Big"));
            assertTrue(e.getMessage().startsWith(file + ": 3.0 GB, more than the 64 MB"), e.getMessage());
        }
    }
}
