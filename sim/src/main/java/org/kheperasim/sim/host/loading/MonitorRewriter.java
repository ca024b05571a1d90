package org.kheperasim.sim.host.loading;

import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * Puts the monitors of contained controller code under the lockstep: before every
 * {@code monitorenter} and {@code monitorexit} a call of
 * {@link org.kheperasim.sim.host.ThreadHooks#monitorEnter} or {@code monitorExit} with the same
 * object; a {@code synchronized} method becomes a plain one whose body is a synchronized block (its
 * monitor entered at the start and left at every return and on the way out of an exception).
 *
 * <p>So a thread of the controller that would block on a monitor another of its threads owns (one
 * that sleeps while holding it, say) gives the turn to the others instead of blocking the whole run;
 * the real monitor is still taken, for threads outside the lockstep (a Swing event thread).
 *
 * <p>The object a {@code monitorenter} locks first goes through {@link MonitorHooks#own}: an object
 * the robot's code does not own (a string literal, a {@code Class} of the API) is locked as the
 * robot's own stand-in ({@link Monitors}). javac's {@code dup; astore n; monitorenter} gets the
 * stand-in before the {@code dup}, so that its temporary holds the stand-in and its
 * {@code aload n; monitorexit} leaves the very monitor entered: the JIT still sees balanced
 * monitors and compiles the method. Any other {@code monitorexit} asks the hook again (the same
 * object always gets the same stand-in). A synchronized method locks {@code this} or its own class,
 * which are the robot's own.
 */
final class MonitorRewriter extends MethodVisitor {
    private static final String HOOKS = CallTargets.THREAD_HOOKS;

    private final boolean synchronizedMethod;
    private final boolean isStatic;
    private final String owner;
    private final boolean frames;
    private final Runnable changed;
    private final boolean classConstants;
    /** A {@code dup} held back, and then an {@code astore} after it: maybe javac's synchronized block. */
    private boolean heldDup;
    private int heldStore = -1;
    /** The local an {@code aload} just read, or -1 when the last instruction was none. */
    private int lastLoad = -1;
    /** The locals that javac's blocks in this method have stored a stand-in in. */
    private final java.util.BitSet standIns = new java.util.BitSet();
    private final Label start = new Label();
    private final Label end = new Label();
    private final Label handler = new Label();

    /**
     * @param next the visitor to write to
     * @param access the method's access flags as the class file has them
     * @param owner internal name of the class
     * @param version the class file's version (stack map frames from 50 on)
     * @param changed told when anything is rewritten
     */
    MonitorRewriter(MethodVisitor next, int access, String owner, int version, Runnable changed) {
        super(Opcodes.ASM9, next);
        this.synchronizedMethod = isRewrittenSynchronized(access, version);
        this.isStatic = (access & Opcodes.ACC_STATIC) != 0;
        this.owner = owner;
        this.frames = (version & 0xFFFF) >= Opcodes.V1_6;
        this.classConstants = (version & 0xFFFF) >= Opcodes.V1_5;
        this.changed = changed;
    }

    /**
     * @return true when a method with these flags loses {@code ACC_SYNCHRONIZED} and gets an
     *     explicit block instead: one with code, in a class file that can load its class constant
     */
    static boolean isRewrittenSynchronized(int access, int version) {
        return (access & Opcodes.ACC_SYNCHRONIZED) != 0 && (access & (Opcodes.ACC_ABSTRACT | Opcodes.ACC_NATIVE)) == 0
                && (version & 0xFFFF) >= Opcodes.V1_5;
    }

    @Override
    public void visitCode() {
        super.visitCode();
        if (synchronizedMethod) {
            changed.run();
            pushLock();
            enter();
            super.visitLabel(start);
        }
    }

    @Override
    public void visitInsn(int opcode) {
        if (opcode == Opcodes.MONITORENTER) {
            changed.run();
            if (heldDup && heldStore >= 0) {
                // javac's block: the temporary gets the stand-in, which its exits then leave.
                int local = heldStore;
                heldDup = false;
                heldStore = -1;
                own();
                super.visitInsn(Opcodes.DUP);
                super.visitVarInsn(Opcodes.ASTORE, local);
                standIns.set(local);
            } else {
                release();
                own();
            }
            enter();
            return;
        }
        if (opcode == Opcodes.DUP) {
            release();
            heldDup = true;
            return;
        }
        int loaded = lastLoad;
        release();
        if (opcode == Opcodes.MONITOREXIT) {
            changed.run();
            if (loaded < 0 || !standIns.get(loaded)) {
                own();
            }
            super.visitInsn(Opcodes.DUP);
            super.visitMethodInsn(Opcodes.INVOKESTATIC, HOOKS, "monitorExit", "(Ljava/lang/Object;)V", false);
            super.visitInsn(Opcodes.MONITOREXIT);
        } else {
            if (synchronizedMethod && opcode >= Opcodes.IRETURN && opcode <= Opcodes.RETURN) {
                exit();
            }
            super.visitInsn(opcode);
        }
    }

    @Override
    public void visitVarInsn(int opcode, int varIndex) {
        if (opcode == Opcodes.ASTORE && heldDup && heldStore < 0) {
            heldStore = varIndex;
            return;
        }
        release();
        super.visitVarInsn(opcode, varIndex);
        if (opcode == Opcodes.ALOAD) {
            lastLoad = varIndex;
        }
    }

    /** Stack: object → the object to lock instead (see {@link MonitorHooks#own}). */
    private void own() {
        if (classConstants) {
            super.visitLdcInsn(Type.getObjectType(owner));
            super.visitMethodInsn(Opcodes.INVOKESTATIC, CallTargets.MONITOR_HOOKS, "own",
                    "(Ljava/lang/Object;Ljava/lang/Class;)Ljava/lang/Object;", false);
        } else {
            super.visitMethodInsn(Opcodes.INVOKESTATIC, CallTargets.MONITOR_HOOKS, "own",
                    "(Ljava/lang/Object;)Ljava/lang/Object;", false);
        }
    }

    /** Write what was held back, as it was, and forget the last load: the next instruction is another. */
    private void release() {
        lastLoad = -1;
        if (heldDup) {
            heldDup = false;
            super.visitInsn(Opcodes.DUP);
            if (heldStore >= 0) {
                super.visitVarInsn(Opcodes.ASTORE, heldStore);
                heldStore = -1;
            }
        }
    }

    @Override
    public void visitIntInsn(int opcode, int operand) {
        release();
        super.visitIntInsn(opcode, operand);
    }

    @Override
    public void visitTypeInsn(int opcode, String type) {
        release();
        super.visitTypeInsn(opcode, type);
    }

    @Override
    public void visitFieldInsn(int opcode, String owner, String name, String descriptor) {
        release();
        super.visitFieldInsn(opcode, owner, name, descriptor);
    }

    @Override
    public void visitMethodInsn(int opcode, String owner, String name, String descriptor, boolean isInterface) {
        release();
        super.visitMethodInsn(opcode, owner, name, descriptor, isInterface);
    }

    @Override
    public void visitInvokeDynamicInsn(String name, String descriptor, org.objectweb.asm.Handle bootstrapMethodHandle,
            Object... bootstrapMethodArguments) {
        release();
        super.visitInvokeDynamicInsn(name, descriptor, bootstrapMethodHandle, bootstrapMethodArguments);
    }

    @Override
    public void visitJumpInsn(int opcode, Label label) {
        release();
        super.visitJumpInsn(opcode, label);
    }

    @Override
    public void visitLabel(Label label) {
        release();
        super.visitLabel(label);
    }

    @Override
    public void visitLdcInsn(Object value) {
        release();
        super.visitLdcInsn(value);
    }

    @Override
    public void visitIincInsn(int varIndex, int increment) {
        release();
        super.visitIincInsn(varIndex, increment);
    }

    @Override
    public void visitTableSwitchInsn(int min, int max, Label dflt, Label... labels) {
        release();
        super.visitTableSwitchInsn(min, max, dflt, labels);
    }

    @Override
    public void visitLookupSwitchInsn(Label dflt, int[] keys, Label[] labels) {
        release();
        super.visitLookupSwitchInsn(dflt, keys, labels);
    }

    @Override
    public void visitMultiANewArrayInsn(String descriptor, int numDimensions) {
        release();
        super.visitMultiANewArrayInsn(descriptor, numDimensions);
    }

    @Override
    public void visitFrame(int type, int numLocal, Object[] local, int numStack, Object[] stack) {
        release();
        super.visitFrame(type, numLocal, local, numStack, stack);
    }

    @Override
    public void visitLineNumber(int line, Label label) {
        release();
        super.visitLineNumber(line, label);
    }

    @Override
    public org.objectweb.asm.AnnotationVisitor visitInsnAnnotation(int typeRef, org.objectweb.asm.TypePath typePath,
            String descriptor, boolean visible) {
        release();
        return super.visitInsnAnnotation(typeRef, typePath, descriptor, visible);
    }

    @Override
    public void visitTryCatchBlock(Label start, Label end, Label handler, String type) {
        release();
        super.visitTryCatchBlock(start, end, handler, type);
    }

    @Override
    public void visitLocalVariable(String name, String descriptor, String signature, Label start,
            Label end, int index) {
        release();
        super.visitLocalVariable(name, descriptor, signature, start, end, index);
    }

    @Override
    public void visitEnd() {
        release();
        super.visitEnd();
    }

    @Override
    public void visitMaxs(int maxStack, int maxLocals) {
        release();
        if (synchronizedMethod) {
            // Whatever is thrown out of the body leaves the monitor first.
            super.visitLabel(end);
            super.visitLabel(handler);
            if (frames) {
                Object[] locals = isStatic ? new Object[0] : new Object[] {owner};
                super.visitFrame(Opcodes.F_FULL, locals.length, locals, 1, new Object[] {"java/lang/Throwable"});
            }
            exit();
            super.visitInsn(Opcodes.ATHROW);
            super.visitTryCatchBlock(start, end, handler, null);
        }
        super.visitMaxs(maxStack, maxLocals);
    }

    /** Stack: lock → (nothing); the lockstep's entry, then the real one. */
    private void enter() {
        super.visitInsn(Opcodes.DUP);
        super.visitMethodInsn(Opcodes.INVOKESTATIC, HOOKS, "monitorEnter", "(Ljava/lang/Object;)V", false);
        super.visitInsn(Opcodes.MONITORENTER);
    }

    /** Leave the synchronized method's monitor (the stack is otherwise untouched). */
    private void exit() {
        pushLock();
        super.visitInsn(Opcodes.DUP);
        super.visitMethodInsn(Opcodes.INVOKESTATIC, HOOKS, "monitorExit", "(Ljava/lang/Object;)V", false);
        super.visitInsn(Opcodes.MONITOREXIT);
    }

    private void pushLock() {
        if (isStatic) {
            super.visitLdcInsn(Type.getObjectType(owner));
        } else {
            super.visitVarInsn(Opcodes.ALOAD, 0);
        }
    }
}
