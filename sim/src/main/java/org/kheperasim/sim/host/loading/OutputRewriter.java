package org.kheperasim.sim.host.loading;

import org.kheperasim.sim.host.ControllerOutput;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * Points contained controller code's {@code System.out} and {@code System.err} at
 * {@link ControllerOutput}, so that what a controller prints reaches the run's console with its
 * simulated time (a {@code GETSTATIC} becomes a call that leaves the same stream type on the stack).
 */
final class OutputRewriter extends MethodVisitor {
    private static final String OUTPUT = Type.getInternalName(ControllerOutput.class);
    private final Runnable changed;

    OutputRewriter(MethodVisitor next, Runnable changed) {
        super(Opcodes.ASM9, next);
        this.changed = changed;
    }

    @Override
    public void visitFieldInsn(int opcode, String owner, String name, String descriptor) {
        if (opcode == Opcodes.GETSTATIC && owner.equals("java/lang/System")
                && descriptor.equals("Ljava/io/PrintStream;")
                && (name.equals("out") || name.equals("err"))) {
            changed.run();
            super.visitMethodInsn(Opcodes.INVOKESTATIC, OUTPUT, name, "()Ljava/io/PrintStream;", false);
            return;
        }
        super.visitFieldInsn(opcode, owner, name, descriptor);
    }
}
