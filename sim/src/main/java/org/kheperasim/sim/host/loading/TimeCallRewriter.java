package org.kheperasim.sim.host.loading;

import java.util.HashSet;
import java.util.Set;
import org.kheperasim.sim.host.SimClock;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassTooLargeException;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.ConstantDynamic;
import org.objectweb.asm.Handle;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodTooLargeException;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * The load-time bytecode rewrite that puts controller code on the simulation clock.
 *
 * <p>In every method of a class it
 * <ul>
 *   <li>replaces calls of {@code Thread.sleep(long)}, {@code Thread.sleep(long, int)},
 *       {@code Thread.sleep(Duration)}, {@code Thread.yield()} and {@code Thread.onSpinWait()} by
 *       the {@link SimClock} method of the same name and descriptor, also when the call is made
 *       through a subclass of {@code Thread} (javac compiles an unqualified {@code sleep(100)} in
 *       {@code class Robot extends Thread} as a call of {@code Robot.sleep}) unless a class between
 *       it and {@code Thread} declares its own method of that name and descriptor;</li>
 *   <li>replaces {@code System.currentTimeMillis()} and {@code System.nanoTime()} by
 *       {@link SimClock#currentTimeMillis()} and {@link SimClock#nanoTime()};</li>
 *   <li>replaces the instance call {@code unit.sleep(long)} on a {@code TimeUnit} by the static
 *       {@link SimClock#sleep(java.util.concurrent.TimeUnit, long)}, which takes the same stack;</li>
 *   <li>does the same for method handles to those methods (method references such as
 *       {@code System::nanoTime}, and {@code MethodHandle} constants);</li>
 *   <li>calls {@link SimClock#checkpoint()} before every backward jump (a jump or switch with a
 *       target that comes earlier in the method), so that a loop which never calls the API can
 *       still be stopped.</li>
 * </ul>
 * Nothing else changes: the inserted call takes and leaves nothing on the operand stack and does
 * not change control flow, so the class's own stack map frames stay valid and are kept.
 */
public final class TimeCallRewriter {

    /** Internal name of the class all rewritten calls go to. */
    static final String SIM_CLOCK = Type.getInternalName(SimClock.class);

    private static final String THREAD = "java/lang/Thread";
    private static final String SYSTEM = "java/lang/System";
    private static final String TIME_UNIT = "java/util/concurrent/TimeUnit";

    /** The static methods of {@code Thread} that {@link SimClock} replaces, as name + descriptor. */
    private static final Set<String> THREAD_STATICS = Set.of(
            "sleep(J)V", "sleep(JI)V", "sleep(Ljava/time/Duration;)V", "yield()V", "onSpinWait()V");

    /** The static methods of {@code System} that {@link SimClock} replaces, as name + descriptor. */
    private static final Set<String> SYSTEM_STATICS = Set.of("currentTimeMillis()J", "nanoTime()J");

    /** The replacement of the instance method {@code TimeUnit.sleep(long)}: the unit comes first. */
    private static final String TIME_UNIT_SLEEP_HOOK = "(L" + TIME_UNIT + ";J)V";

    /**
     * The newest class file version this rewriter accepts: what both ASM 9.8 (up to Java 25) and
     * the running JVM can read.
     */
    private static final int NEWEST_VERSION = Math.min(Opcodes.V25, 44 + Runtime.version().feature());

    private static final int CLASS_FILE_MAGIC = 0xCAFEBABE;

    private TimeCallRewriter() {
    }

    /**
     * Rewrite one class file.
     *
     * @param classFile the class file's bytes (not modified)
     * @param lookup answers whether a static call through a class other than {@code Thread}
     *     reaches {@code Thread}'s method; it must not load classes through the loader that is
     *     defining this one
     * @return the rewritten class file, or {@code classFile} itself when nothing had to change
     * @throws UnsupportedClassVersionError when the class was compiled for a newer Java than the
     *     rewriter or the running JVM supports (the message says to compile with
     *     {@code --release 17})
     * @throws ClassFormatError when the bytes are not a well-formed class file, or a method grows
     *     too large for the class file format once checkpoints are inserted
     */
    public static byte[] rewrite(byte[] classFile, HierarchyLookup lookup) {
        checkHeader(classFile);
        ClassReader reader;
        ClassWriter writer;
        ClassRewriter rewriter;
        try {
            reader = new ClassReader(classFile);
            writer = new ClassWriter(reader, ClassWriter.COMPUTE_MAXS);
            rewriter = new ClassRewriter(writer, lookup);
            reader.accept(rewriter, 0);
        } catch (RuntimeException e) {
            // ASM reports a malformed class file with whatever runtime exception it runs into.
            throw withCause(new ClassFormatError("not a well-formed class file (" + e + ")"), e);
        }
        if (!rewriter.changed) {
            return classFile;
        }
        try {
            return writer.toByteArray();
        } catch (MethodTooLargeException e) {
            throw withCause(new ClassFormatError("method " + e.getMethodName() + e.getDescriptor() + " of "
                    + e.getClassName() + " is too large once loop checkpoints are added: split it into"
                    + " smaller methods"), e);
        } catch (ClassTooLargeException e) {
            throw withCause(new ClassFormatError("class " + e.getClassName()
                    + " is too large once its calls are rewritten: split it into smaller classes"), e);
        }
    }

    /** Reject what is not a class file, or one too new to read, with a message a student can act on. */
    private static void checkHeader(byte[] classFile) {
        if (classFile.length < 8 || readInt(classFile, 0) != CLASS_FILE_MAGIC) {
            throw new ClassFormatError("not a class file (it does not start with 0xCAFEBABE)");
        }
        int major = ((classFile[6] & 0xFF) << 8) | (classFile[7] & 0xFF);
        if (major > NEWEST_VERSION) {
            throw new UnsupportedClassVersionError("compiled for Java " + (major - 44) + " (class file version "
                    + major + "), but the simulator loads classes up to Java " + (NEWEST_VERSION - 44)
                    + ": compile it with --release 17");
        }
    }

    private static int readInt(byte[] b, int offset) {
        return ((b[offset] & 0xFF) << 24) | ((b[offset + 1] & 0xFF) << 16)
                | ((b[offset + 2] & 0xFF) << 8) | (b[offset + 3] & 0xFF);
    }

    private static <T extends Throwable> T withCause(T error, Throwable cause) {
        error.initCause(cause);
        return error;
    }

    /** Rewrites every method and remembers whether anything changed. */
    private static final class ClassRewriter extends ClassVisitor {
        private final HierarchyLookup lookup;
        private boolean changed;

        ClassRewriter(ClassVisitor next, HierarchyLookup lookup) {
            super(Opcodes.ASM9, next);
            this.lookup = lookup;
        }

        @Override
        public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                String[] exceptions) {
            MethodVisitor next = super.visitMethod(access, name, descriptor, signature, exceptions);
            return next == null ? null : new MethodRewriter(next);
        }

        /**
         * The descriptor of the {@link SimClock} method (of the same name) that replaces a call, or
         * null when the call stays.
         *
         * @param opcode {@link Opcodes#INVOKESTATIC} or {@link Opcodes#INVOKEVIRTUAL}; any other
         *     kind of call always stays
         */
        private String hook(int opcode, String owner, String name, String descriptor) {
            if (opcode == Opcodes.INVOKESTATIC) {
                String method = name + descriptor;
                if (THREAD_STATICS.contains(method)
                        && (owner.equals(THREAD) || lookup.resolvesToThread(owner, name, descriptor))) {
                    return descriptor;
                }
                if (owner.equals(SYSTEM) && SYSTEM_STATICS.contains(method)) {
                    return descriptor;
                }
            } else if (opcode == Opcodes.INVOKEVIRTUAL && owner.equals(TIME_UNIT)
                    && name.equals("sleep") && descriptor.equals("(J)V")) {
                return TIME_UNIT_SLEEP_HOOK;
            }
            return null;
        }

        /** A loadable constant with every method handle to a replaced method pointed at its hook. */
        private Object constant(Object value) {
            if (value instanceof Handle handle) {
                int opcode = switch (handle.getTag()) {
                    case Opcodes.H_INVOKESTATIC -> Opcodes.INVOKESTATIC;
                    case Opcodes.H_INVOKEVIRTUAL -> Opcodes.INVOKEVIRTUAL;
                    default -> 0;
                };
                String hook = hook(opcode, handle.getOwner(), handle.getName(), handle.getDesc());
                if (hook == null) {
                    return handle;
                }
                changed = true;
                return new Handle(Opcodes.H_INVOKESTATIC, SIM_CLOCK, handle.getName(), hook, false);
            }
            if (value instanceof ConstantDynamic dynamic) {
                Object[] arguments = new Object[dynamic.getBootstrapMethodArgumentCount()];
                for (int i = 0; i < arguments.length; i++) {
                    arguments[i] = dynamic.getBootstrapMethodArgument(i);
                }
                Object[] mapped = constants(arguments);
                return mapped == arguments ? dynamic : new ConstantDynamic(dynamic.getName(),
                        dynamic.getDescriptor(), dynamic.getBootstrapMethod(), mapped);
            }
            return value;
        }

        /** @return {@code values} itself when no element changed, else a mapped copy */
        private Object[] constants(Object[] values) {
            Object[] mapped = values;
            for (int i = 0; i < values.length; i++) {
                Object value = constant(values[i]);
                if (value != values[i]) {
                    if (mapped == values) {
                        mapped = values.clone();
                    }
                    mapped[i] = value;
                }
            }
            return mapped;
        }

        /** Redirects time calls and marks the back-edges of one method. */
        private final class MethodRewriter extends MethodVisitor {
            /** The labels already passed in the instruction stream: a jump to one of them goes back. */
            private final Set<Label> passed = new HashSet<>();

            MethodRewriter(MethodVisitor next) {
                super(Opcodes.ASM9, next);
            }

            @Override
            public void visitLabel(Label label) {
                passed.add(label);
                super.visitLabel(label);
            }

            @Override
            public void visitJumpInsn(int opcode, Label label) {
                // A JSR (pre-Java 6 subroutine call) returns with RET: jumping back with it is no loop.
                if (opcode != Opcodes.JSR && passed.contains(label)) {
                    checkpoint();
                }
                super.visitJumpInsn(opcode, label);
            }

            @Override
            public void visitTableSwitchInsn(int min, int max, Label dflt, Label... labels) {
                if (anyPassed(dflt, labels)) {
                    checkpoint();
                }
                super.visitTableSwitchInsn(min, max, dflt, labels);
            }

            @Override
            public void visitLookupSwitchInsn(Label dflt, int[] keys, Label[] labels) {
                if (anyPassed(dflt, labels)) {
                    checkpoint();
                }
                super.visitLookupSwitchInsn(dflt, keys, labels);
            }

            @Override
            public void visitMethodInsn(int opcode, String owner, String name, String descriptor,
                    boolean isInterface) {
                String hook = hook(opcode, owner, name, descriptor);
                if (hook == null) {
                    super.visitMethodInsn(opcode, owner, name, descriptor, isInterface);
                } else {
                    changed = true;
                    super.visitMethodInsn(Opcodes.INVOKESTATIC, SIM_CLOCK, name, hook, false);
                }
            }

            @Override
            public void visitInvokeDynamicInsn(String name, String descriptor, Handle bootstrapMethod,
                    Object... bootstrapMethodArguments) {
                super.visitInvokeDynamicInsn(name, descriptor, bootstrapMethod,
                        constants(bootstrapMethodArguments));
            }

            @Override
            public void visitLdcInsn(Object value) {
                super.visitLdcInsn(constant(value));
            }

            private boolean anyPassed(Label dflt, Label[] labels) {
                if (passed.contains(dflt)) {
                    return true;
                }
                for (Label label : labels) {
                    if (passed.contains(label)) {
                        return true;
                    }
                }
                return false;
            }

            private void checkpoint() {
                changed = true;
                super.visitMethodInsn(Opcodes.INVOKESTATIC, SIM_CLOCK, "checkpoint", "()V", false);
            }
        }
    }
}
