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
 */
final class MonitorRewriter extends MethodVisitor {
    private static final String HOOKS = CallTargets.THREAD_HOOKS;

    private final boolean synchronizedMethod;
    private final boolean isStatic;
    private final String owner;
    private final boolean frames;
    private final Runnable changed;
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
            enter();
        } else if (opcode == Opcodes.MONITOREXIT) {
            changed.run();
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
    public void visitMaxs(int maxStack, int maxLocals) {
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
