package org.kheperasim.sim.host.loading;

import java.util.HashMap;
import java.util.Map;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Sets what a wall-clock constructor of {@code java.util} makes ({@code new GregorianCalendar()},
 * each overload without a date, and {@code new Date()}) to the simulated clock: after the
 * constructor's {@code invokespecial} it calls the {@link CalendarHooks} method
 * {@link CallTargets#afterConstructor} names on the new object, the copy that {@code new}'s
 * {@code dup} left on the stack, or on {@code this} when the call is the {@code super()} of a
 * subclass's constructor. The JDK reads the wall clock inside those constructors, where the rewrite
 * of {@code System.currentTimeMillis()} does not reach. The inserted instructions take from the
 * stack what they put on it and sit between two instructions with no label between, so the
 * method's stack map frames stay valid.
 */
final class ClockConstructorRewriter extends MethodVisitor {
    private final CallTargets targets;
    /** Whether the method is a constructor, where an {@code invokespecial} may be its {@code super()}. */
    private final boolean constructor;
    private final Runnable changed;
    /**
     * By class, how many objects are made ({@code new}) and not yet constructed: a constructor call
     * with none pending is a subclass's {@code super()} (javac nests each {@code new} and its
     * constructor call like brackets).
     */
    private final Map<String, Integer> pendingNew = new HashMap<>();

    ClockConstructorRewriter(MethodVisitor next, CallTargets targets, boolean constructor, Runnable changed) {
        super(Opcodes.ASM9, next);
        this.targets = targets;
        this.constructor = constructor;
        this.changed = changed;
    }

    @Override
    public void visitTypeInsn(int opcode, String type) {
        if (opcode == Opcodes.NEW && CallTargets.readsTheClockWhenMade(type)) {
            pendingNew.merge(type, 1, Integer::sum);
        }
        super.visitTypeInsn(opcode, type);
    }

    @Override
    public void visitMethodInsn(int opcode, String owner, String name, String descriptor, boolean isInterface) {
        super.visitMethodInsn(opcode, owner, name, descriptor, isInterface);
        if (opcode != Opcodes.INVOKESPECIAL || !name.equals("<init>") || !CallTargets.readsTheClockWhenMade(owner)) {
            return;
        }
        int pending = pendingNew.getOrDefault(owner, 0);
        if (pending > 0) {
            pendingNew.put(owner, pending - 1);
        }
        CallTargets.Target hook = targets.afterConstructor(owner, descriptor);
        if (hook == null || pending == 0 && !constructor) {
            return;
        }
        changed.run();
        if (pending > 0) {
            super.visitInsn(Opcodes.DUP);
        } else {
            super.visitVarInsn(Opcodes.ALOAD, 0);
        }
        super.visitMethodInsn(Opcodes.INVOKESTATIC, hook.owner(), hook.name(), hook.descriptor(), false);
    }
}
