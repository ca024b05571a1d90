package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.testfixtures.Cli;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Issue 35, item 8 (class files): {@code run} of a controller whose class file is too new,
 * malformed, not a class file at all, or far too large (a 3 GB sparse file, never read) exits 2
 * with one line naming the file and the fix, and no stack trace; so does one whose helper class is
 * too new, before it runs.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class BadClassFileCliTest {
    /** The newest class file version the simulator reads on this JVM (ASM 9.8 reads up to Java 25). */
    private static final int NEWEST = Math.min(69, 44 + Runtime.version().feature());

    @TempDir
    Path dir;

    private String out;
    private String err;

    private int main(String... args) {
        Cli.Printed p = Cli.main(args);
        out = p.out();
        err = p.err();
        return p.code();
    }

    private int run(String controller, String... more) {
        List<String> args = new java.util.ArrayList<>(List.of("run", "--arena", "lab", "--controller", controller,
                "--classpath", dir.toString(), "--seconds", "1", "--quiet"));
        args.addAll(List.of(more));
        return main(args.toArray(new String[0]));
    }

    /** A class {@code name} of that class file version, extending {@code superName}, with a public constructor. */
    private static byte[] classFile(String name, int version, String superName) {
        ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
        w.visit(version, Opcodes.ACC_PUBLIC | Opcodes.ACC_SUPER, name, null, superName, null);
        MethodVisitor init = w.visitMethod(Opcodes.ACC_PUBLIC, "<init>", "()V", null, null);
        init.visitCode();
        init.visitVarInsn(Opcodes.ALOAD, 0);
        init.visitMethodInsn(Opcodes.INVOKESPECIAL, superName, "<init>", "()V", false);
        init.visitInsn(Opcodes.RETURN);
        init.visitMaxs(0, 0);
        init.visitEnd();
        w.visitEnd();
        return w.toByteArray();
    }

    /** The error output is the one line given: no stack trace, nothing else. */
    private void assertOneLine(String expected) {
        assertEquals(expected + System.lineSeparator(), err, "stdout: " + out);
    }

    @Test
    void aClassFileForANewerJavaIsRefusedInOneLineWithTheFix() throws Exception {
        Path file = dir.resolve("TooNew.class");
        Files.write(file, classFile("TooNew", NEWEST + 1, "java/lang/Object"));
        assertEquals(ExitCodes.BAD_INPUT, run("TooNew"));
        int running = Runtime.version().feature();
        String newest = NEWEST - 44 == running ? "this Java " + running
                : "Java " + (NEWEST - 44) + ", the newest this simulator reads";
        assertOneLine("khepera-sim: error: controller TooNew cannot be loaded: " + file + ": compiled for Java "
                + (NEWEST + 1 - 44) + " (class file version " + (NEWEST + 1) + "), newer than " + newest
                + "; compile it with `--release 17`");
        assertEquals(ExitCodes.BAD_INPUT, run("TooNew", "--trusted"), "trusted code is read alike: " + err);
        assertTrue(err.startsWith("khepera-sim: error: controller TooNew cannot be loaded: " + file), err);
    }

    @Test
    void aMalformedClassFileIsRefusedInOneLine() throws Exception {
        byte[] good = classFile("Broken", 61, "java/lang/Object");
        Files.write(dir.resolve("Broken.class"), java.util.Arrays.copyOf(good, 20)); // cut short in the constant pool
        assertEquals(ExitCodes.BAD_INPUT, run("Broken"));
        assertTrue(err.startsWith("khepera-sim: error: controller Broken cannot be loaded: " + dir.resolve("Broken.class")
                + ": not a well-formed class file ("), err);
        assertTrue(err.endsWith("compile the source again with `javac --release 17`" + System.lineSeparator()), err);
        assertEquals(1, err.lines().count(), err);

        Files.writeString(dir.resolve("Text.class"), "public class Text {}\n");
        assertEquals(ExitCodes.BAD_INPUT, run("Text"));
        assertOneLine("khepera-sim: error: controller Text cannot be loaded: " + dir.resolve("Text.class")
                + ": not a class file (it does not start with 0xCAFEBABE); compile the source again with `javac --release 17`");
    }

    @Test
    void aThreeGigabyteClassFileIsRefusedWithoutReadingIt() throws Exception {
        Path big = dir.resolve("Big.class");
        try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(3L << 30); // sparse: no disk, and reading it would need 3 GB of heap
        }
        long start = System.nanoTime();
        assertEquals(ExitCodes.BAD_INPUT, run("Big"));
        assertOneLine("khepera-sim: error: controller Big cannot be loaded: " + big + ": 3.0 GB, more than the 64 MB a"
                + " class file or resource may have (is it one? remove it, or keep large data out of the controller's folder)");
        assertTrue(System.nanoTime() - start < 20_000_000_000L, "refused without reading it");
    }

    @Test
    void aControllerWhoseHelperIsTooNewIsRefusedBeforeItRuns() throws Exception {
        // The controller is fine; the helper it creates was compiled for a newer Java.
        ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
        w.visit(61, Opcodes.ACC_PUBLIC | Opcodes.ACC_SUPER, "Uses", null, "org/kheperasim/api/Controller", null);
        MethodVisitor init = w.visitMethod(Opcodes.ACC_PUBLIC, "<init>", "()V", null, null);
        init.visitCode();
        init.visitVarInsn(Opcodes.ALOAD, 0);
        init.visitMethodInsn(Opcodes.INVOKESPECIAL, "org/kheperasim/api/Controller", "<init>", "()V", false);
        init.visitInsn(Opcodes.RETURN);
        init.visitMaxs(0, 0);
        init.visitEnd();
        MethodVisitor work = w.visitMethod(Opcodes.ACC_PROTECTED, "doWork", "()V", null, null);
        work.visitCode();
        work.visitTypeInsn(Opcodes.NEW, "Helper");
        work.visitInsn(Opcodes.DUP);
        work.visitMethodInsn(Opcodes.INVOKESPECIAL, "Helper", "<init>", "()V", false);
        work.visitInsn(Opcodes.POP);
        work.visitInsn(Opcodes.RETURN);
        work.visitMaxs(0, 0);
        work.visitEnd();
        w.visitEnd();
        Files.write(dir.resolve("Uses.class"), w.toByteArray());
        Files.write(dir.resolve("Helper.class"), classFile("Helper", NEWEST + 1, "java/lang/Object"));
        assertEquals(ExitCodes.BAD_INPUT, run("Uses"));
        assertTrue(err.startsWith("khepera-sim: error: controller Uses cannot be loaded: " + dir.resolve("Helper.class")
                + ": compiled for Java " + (NEWEST + 1 - 44)), err);
        assertEquals(1, err.lines().count(), err);
    }
}
