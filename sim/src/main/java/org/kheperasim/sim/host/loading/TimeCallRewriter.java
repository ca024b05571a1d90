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
 *       {@link SimClock#currentTimeMillis()} and {@link SimClock#nanoTime()}, and
 *       {@code Calendar.getInstance(...)} by {@link CalendarHooks}' method of the same name and
 *       descriptor (a calendar set to the simulated clock), and sets what {@code new GregorianCalendar()}
 *       and {@code new Date()} make to the simulated clock too ({@link ClockConstructorRewriter});</li>
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
 *
 * <p>Untrusted controller code is also contained (see {@link CallTargets} for the calls that go to
 * {@link org.kheperasim.sim.host.Containment} and the other hooks, and for the parallel streams made
 * sequential; {@link ControllerCheck} refuses what the allowlist does not allow before this rewrite
 * runs): every handler that catches {@code Throwable} or {@code Error} first rethrows a stop of
 * the simulator, so a catch-all loop cannot keep a stopped controller alive.
 */
public final class TimeCallRewriter {

    /** Internal name of the class all rewritten calls go to. */
    static final String SIM_CLOCK = Type.getInternalName(SimClock.class);


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
        return rewrite(classFile, lookup, false);
    }

    /**
     * Rewrite one class file, and with {@code contained} also put its escapes, threads, monitors,
     * output and resource reads under the simulator's control (see {@link CallTargets}); what it may
     * use at all is {@link ControllerCheck}'s to decide, before.
     *
     * @param classFile the class file's bytes (not modified)
     * @param lookup see {@link #rewrite(byte[], HierarchyLookup)}
     * @param contained true for untrusted controller code
     * @return the rewritten class file, or {@code classFile} itself when nothing had to change
     */
    public static byte[] rewrite(byte[] classFile, HierarchyLookup lookup, boolean contained) {
        ClassFileHeader.check(classFile);
        ClassReader reader;
        ClassWriter writer;
        ClassRewriter rewriter;
        try {
            reader = new ClassReader(classFile);
            writer = new ClassWriter(reader, ClassWriter.COMPUTE_MAXS);
            rewriter = new ClassRewriter(writer, lookup, contained);
            reader.accept(rewriter, 0);
        } catch (RuntimeException e) {
            // ASM reports a malformed class file with whatever runtime exception it runs into.
            throw withCause(new ClassFormatError(ClassFileHeader.malformed(null, e)), e);
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

    private static <T extends Throwable> T withCause(T error, Throwable cause) {
        error.initCause(cause);
        return error;
    }

    /** Rewrites every method and remembers whether anything changed. */
    private static final class ClassRewriter extends ClassVisitor {
        private final CallTargets targets;
        private final boolean contained;
        private boolean changed;
        private String className;
        private int version;

        ClassRewriter(ClassVisitor next, HierarchyLookup lookup, boolean contained) {
            super(Opcodes.ASM9, next);
            this.targets = new CallTargets(lookup, contained);
            this.contained = contained;
        }

        @Override
        public void visit(int version, int access, String name, String signature, String superName,
                String[] interfaces) {
            className = name;
            this.version = version;
            super.visit(version, access, name, signature, superName, interfaces);
        }

        @Override
        public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                String[] exceptions) {
            if (!contained) {
                MethodVisitor next = super.visitMethod(access, name, descriptor, signature, exceptions);
                return next == null ? null : new MethodRewriter(clock(next, name));
            }
            // Contained code's monitors join the lockstep: a synchronized method gets an explicit block.
            int kept = MonitorRewriter.isRewrittenSynchronized(access, version)
                    ? access & ~Opcodes.ACC_SYNCHRONIZED : access;
            MethodVisitor next = super.visitMethod(kept, name, descriptor, signature, exceptions);
            return next == null ? null
                    : new MethodRewriter(clock(new MonitorRewriter(new OutputRewriter(next, () -> changed = true),
                            access, className, version, () -> changed = true), name));
        }

        private MethodVisitor clock(MethodVisitor next, String method) {
            return new ClockConstructorRewriter(next, targets, method.equals("<init>"), () -> changed = true);
        }

        /** A loadable constant with every method handle to a replaced method pointed at its hook. */
        private Object constant(Object value) {
            if (value instanceof Handle handle && handle.getTag() == Opcodes.H_NEWINVOKESPECIAL) {
                CallTargets.Target factory = targets.constructorReference(handle.getOwner(), handle.getDesc());
                if (factory == null) {
                    return handle;
                }
                changed = true;
                return new Handle(Opcodes.H_INVOKESTATIC, factory.owner(), factory.name(), factory.descriptor(), false);
            }
            if (value instanceof Handle handle) {
                int opcode = switch (handle.getTag()) {
                    case Opcodes.H_INVOKESTATIC -> Opcodes.INVOKESTATIC;
                    case Opcodes.H_INVOKEVIRTUAL -> Opcodes.INVOKEVIRTUAL;
                    default -> 0;
                };
                CallTargets.Target hook = targets.of(opcode, handle.getOwner(), handle.getName(), handle.getDesc());
                if (hook == null) {
                    String renamed = targets.renamed(handle.getOwner(), handle.getName(), handle.getDesc());
                    if (renamed == null) {
                        return handle;
                    }
                    changed = true;
                    return new Handle(handle.getTag(), handle.getOwner(), renamed, handle.getDesc(),
                            handle.isInterface());
                }
                changed = true;
                return new Handle(Opcodes.H_INVOKESTATIC, hook.owner(), hook.name(), hook.descriptor(), false);
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
                rethrowStops();
                passed.add(label);
                super.visitLabel(label);
                if (catchAlls.contains(label)) {
                    atCatchAll = true;
                }
            }

            @Override
            public void visitJumpInsn(int opcode, Label label) {
                rethrowStops();
                // A JSR (pre-Java 6 subroutine call) returns with RET: jumping back with it is no loop.
                if (opcode != Opcodes.JSR && passed.contains(label)) {
                    checkpoint();
                }
                super.visitJumpInsn(opcode, label);
            }

            @Override
            public void visitTableSwitchInsn(int min, int max, Label dflt, Label... labels) {
                rethrowStops();
                if (anyPassed(dflt, labels)) {
                    checkpoint();
                }
                super.visitTableSwitchInsn(min, max, dflt, labels);
            }

            @Override
            public void visitLookupSwitchInsn(Label dflt, int[] keys, Label[] labels) {
                rethrowStops();
                if (anyPassed(dflt, labels)) {
                    checkpoint();
                }
                super.visitLookupSwitchInsn(dflt, keys, labels);
            }

            /** Handlers of catch-alls ({@code Throwable}, {@code Error}): a stop must not end in them. */
            private final Set<Label> catchAlls = new HashSet<>();
            private boolean atCatchAll;

            @Override
            public void visitTryCatchBlock(Label start, Label end, Label handler, String type) {
                if (contained && ("java/lang/Throwable".equals(type) || "java/lang/Error".equals(type))) {
                    catchAlls.add(handler);
                }
                super.visitTryCatchBlock(start, end, handler, type);
            }

            @Override
            public void visitFrame(int type, int numLocal, Object[] local, int numStack, Object[] stack) {
                super.visitFrame(type, numLocal, local, numStack, stack);
                rethrowStops();
            }

            /** At a catch-all handler, with the exception on the stack: rethrow it if it is a stop. */
            private void rethrowStops() {
                if (atCatchAll) {
                    atCatchAll = false;
                    changed = true;
                    super.visitInsn(Opcodes.DUP);
                    super.visitMethodInsn(Opcodes.INVOKESTATIC, CallTargets.CONTAINMENT, "rethrowIfStopped",
                            "(Ljava/lang/Throwable;)V", false);
                }
            }

            @Override
            public void visitInsn(int opcode) {
                rethrowStops();
                super.visitInsn(opcode);
            }

            @Override
            public void visitIntInsn(int opcode, int operand) {
                rethrowStops();
                super.visitIntInsn(opcode, operand);
            }

            @Override
            public void visitIincInsn(int varIndex, int increment) {
                rethrowStops();
                super.visitIincInsn(varIndex, increment);
            }

            @Override
            public void visitVarInsn(int opcode, int varIndex) {
                rethrowStops();
                super.visitVarInsn(opcode, varIndex);
            }

            @Override
            public void visitMethodInsn(int opcode, String owner, String name, String descriptor,
                    boolean isInterface) {
                rethrowStops();
                CallTargets.Target hook = targets.of(opcode, owner, name, descriptor);
                if (hook == null) {
                    String renamed = targets.renamed(owner, name, descriptor);
                    changed |= renamed != null;
                    super.visitMethodInsn(opcode, owner, renamed != null ? renamed : name, descriptor, isInterface);
                } else if (hook.caller() && (version & 0xFFFF) >= Opcodes.V1_5) {
                    // The hook's table is the calling class's loader's: it gets the class, a constant.
                    changed = true;
                    super.visitLdcInsn(Type.getObjectType(className));
                    super.visitMethodInsn(Opcodes.INVOKESTATIC, hook.owner(), hook.name(),
                            hook.descriptorWithCaller(), false);
                } else {
                    changed = true;
                    super.visitMethodInsn(Opcodes.INVOKESTATIC, hook.owner(), hook.name(), hook.descriptor(), false);
                }
            }

            @Override
            public void visitFieldInsn(int opcode, String owner, String name, String descriptor) {
                rethrowStops();
                super.visitFieldInsn(opcode, owner, name, descriptor);
            }

            @Override
            public void visitTypeInsn(int opcode, String type) {
                rethrowStops();
                super.visitTypeInsn(opcode, type);
            }

            @Override
            public void visitInvokeDynamicInsn(String name, String descriptor, Handle bootstrapMethod,
                    Object... bootstrapMethodArguments) {
                rethrowStops();
                super.visitInvokeDynamicInsn(name, descriptor, bootstrapMethod,
                        constants(bootstrapMethodArguments));
            }

            @Override
            public void visitLdcInsn(Object value) {
                rethrowStops();
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
