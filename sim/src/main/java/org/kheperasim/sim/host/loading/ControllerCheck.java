package org.kheperasim.sim.host.loading;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import org.kheperasim.sim.host.loading.ControllerPolicy.Refusal;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.ConstantDynamic;
import org.objectweb.asm.Handle;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * The load-time check of untrusted controller code against {@link ControllerPolicy}: every use a
 * class file makes (calls, field accesses, types, constants, method handles, bootstrap methods, its
 * superclass and interfaces, a finalizer it declares), and, before a controller's first class is
 * defined, every class of the controller's own that it can reach, so that a helper class breaking a
 * rule refuses the controller before its run rather than in the middle of it. Nothing is loaded or
 * run: the check reads class files.
 */
final class ControllerCheck {
    private final ControllerPolicy policy;
    private final Function<String, byte[]> localClassFile;
    private final Function<String, String> where;
    /** Classes that passed: checked once per loader. */
    private final Set<String> passed = new HashSet<>();
    /** True for trusted code: only that every class file it reaches can be read, no use refused. */
    private final boolean headersOnly;

    /**
     * @param policy what is allowed
     * @param localClassFile the class file the loader would define for an internal name, or null
     *     when the class is not the loader's own
     */
    ControllerCheck(ControllerPolicy policy, Function<String, byte[]> localClassFile) {
        this(policy, localClassFile, name -> name + ".class");
    }

    /**
     * @param policy what is allowed
     * @param localClassFile see {@link #ControllerCheck(ControllerPolicy, Function)}
     * @param where the file a class of the loader's own comes from, for messages
     */
    ControllerCheck(ControllerPolicy policy, Function<String, byte[]> localClassFile, Function<String, String> where) {
        this(policy, localClassFile, where, false);
    }

    /**
     * @param headersOnly true for trusted code: {@link #checkReachable} refuses only class files it
     *     cannot read (too new, malformed), so that one reached in the middle of a run is refused
     *     before it instead, in one line; no use is refused
     */
    ControllerCheck(ControllerPolicy policy, Function<String, byte[]> localClassFile, Function<String, String> where,
            boolean headersOnly) {
        this.policy = policy;
        this.localClassFile = localClassFile;
        this.where = where;
        this.headersOnly = headersOnly;
    }

    /**
     * Check a class of the loader's own and every class of its own it reaches, each once.
     *
     * @param internalName the class
     * @throws ControllerPolicyError naming the first use refused (by line) in the first class
     *     found that has one
     * @throws ClassFormatError naming the file of a class it reaches that is no well-formed class
     *     file, or ({@link UnsupportedClassVersionError}) one compiled for a newer Java: refused
     *     before any class is defined, not in the middle of the run
     */
    synchronized void checkReachable(String internalName) {
        Deque<String> open = new ArrayDeque<>(List.of(internalName));
        Set<String> seen = new HashSet<>();
        List<String> checked = new ArrayList<>();
        while (!open.isEmpty()) {
            String name = open.removeFirst();
            if (passed.contains(name) || !seen.add(name)) {
                continue;
            }
            byte[] classFile = localClassFile.apply(name);
            if (classFile == null) {
                continue;
            }
            ClassFileHeader.check(classFile, where.apply(name));
            open.addAll(check(classFile, where.apply(name)));
            checked.add(name);
        }
        // Only now: a class is taken as passed once everything it reaches has passed too.
        passed.addAll(checked);
    }

    /**
     * Check one class file.
     *
     * @param where its file, for messages
     * @return the internal names of the classes it refers to
     * @throws ClassFormatError when it is malformed
     * @throws ControllerPolicyError naming its first use refused, by source line
     */
    Set<String> check(byte[] classFile, String where) {
        Visitor visitor = new Visitor();
        try {
            new ClassReader(classFile).accept(visitor, ClassReader.SKIP_FRAMES);
        } catch (RuntimeException e) { // ASM's way to say the file is malformed
            throw withCause(new ClassFormatError(ClassFileHeader.malformed(where, e)), e);
        }
        visitor.refusals.sort(Comparator.comparingInt(Found::line));
        if (!visitor.refusals.isEmpty() && !headersOnly) {
            Found first = visitor.refusals.get(0);
            throw ControllerPolicy.error(visitor.className, visitor.source, first.line(), first.refusal());
        }
        return visitor.referenced;
    }

    private static <T extends Throwable> T withCause(T error, Throwable cause) {
        error.initCause(cause);
        return error;
    }

    /** A refused use and its line (the class's first line for its superclass and interfaces). */
    private record Found(int line, Refusal refusal) {
    }

    private final class Visitor extends ClassVisitor {
        final List<Found> refusals = new ArrayList<>();
        final Set<String> referenced = new LinkedHashSet<>();
        String className;
        String source;
        private String superName;
        private final List<String> interfaces = new ArrayList<>();
        private int firstLine = Integer.MAX_VALUE;

        Visitor() {
            super(Opcodes.ASM9);
        }

        @Override
        public void visit(int version, int access, String name, String signature, String superName,
                String[] interfaces) {
            className = name;
            this.superName = superName;
            if (superName != null) {
                referenced.add(superName);
            }
            if (interfaces != null) {
                this.interfaces.addAll(List.of(interfaces));
                referenced.addAll(this.interfaces);
            }
        }

        @Override
        public void visitSource(String file, String debug) {
            source = file;
        }

        @Override
        public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                String[] exceptions) {
            boolean finalizer = name.equals("finalize") && descriptor.equals("()V")
                    && (access & Opcodes.ACC_STATIC) == 0;
            return new Instructions(finalizer);
        }

        @Override
        public void visitEnd() {
            int line = firstLine == Integer.MAX_VALUE ? -1 : firstLine;
            List<Found> declaration = new ArrayList<>();
            if (superName != null) {
                Refusal r = policy.supertype(superName, "extends");
                if (r != null) {
                    declaration.add(new Found(line, r));
                }
            }
            for (String i : interfaces) {
                Refusal r = policy.supertype(i, "implements");
                if (r != null) {
                    declaration.add(new Found(line, r));
                }
            }
            refusals.addAll(0, declaration); // the class's declaration comes before its code
        }

        void add(int line, Refusal refusal) {
            if (refusal != null) {
                refusals.add(new Found(line, refusal));
            }
        }

        void line(int line) {
            firstLine = Math.min(firstLine, line);
        }

        /** Checks the uses of one method; a finalizer is refused at its first line. */
        private final class Instructions extends MethodVisitor {
            private final boolean finalizer;
            private int line = -1;

            Instructions(boolean finalizer) {
                super(Opcodes.ASM9);
                this.finalizer = finalizer;
            }

            @Override
            public void visitLineNumber(int number, Label start) {
                if (finalizer && line < 0) {
                    add(number, policy.finalizer());
                }
                line = number;
                line(number);
            }

            @Override
            public void visitEnd() {
                if (finalizer && line < 0) {
                    add(-1, policy.finalizer()); // no line numbers, or abstract
                }
            }

            @Override
            public void visitMethodInsn(int opcode, String owner, String name, String descriptor, boolean isInterface) {
                referenced.add(owner);
                add(line, policy.method(owner, name, descriptor, false));
            }

            @Override
            public void visitFieldInsn(int opcode, String owner, String name, String descriptor) {
                referenced.add(owner);
                add(line, policy.field(owner, name));
            }

            @Override
            public void visitTypeInsn(int opcode, String type) {
                referenced.add(type);
                add(line, policy.type(type));
            }

            @Override
            public void visitMultiANewArrayInsn(String descriptor, int numDimensions) {
                add(line, policy.type(descriptor));
            }

            @Override
            public void visitTryCatchBlock(Label start, Label end, Label handler, String type) {
                if (type != null) {
                    referenced.add(type);
                }
            }

            @Override
            public void visitLdcInsn(Object value) {
                constant(value);
            }

            @Override
            public void visitInvokeDynamicInsn(String name, String descriptor, Handle bootstrap, Object... arguments) {
                bootstrap(bootstrap, arguments);
            }

            private void bootstrap(Handle bootstrap, Object[] arguments) {
                referenced.add(bootstrap.getOwner());
                add(line, policy.method(bootstrap.getOwner(), bootstrap.getName(), bootstrap.getDesc(), true));
                for (Object a : arguments) {
                    constant(a);
                }
            }

            private void constant(Object value) {
                if (value instanceof Type type && (type.getSort() == Type.OBJECT || type.getSort() == Type.ARRAY)) {
                    String name = type.getSort() == Type.OBJECT ? type.getInternalName() : type.getDescriptor();
                    if (type.getSort() == Type.OBJECT) {
                        referenced.add(name);
                    }
                    add(line, policy.type(name));
                } else if (value instanceof Handle handle) {
                    referenced.add(handle.getOwner());
                    int tag = handle.getTag();
                    boolean field = tag == Opcodes.H_GETFIELD || tag == Opcodes.H_GETSTATIC || tag == Opcodes.H_PUTFIELD
                            || tag == Opcodes.H_PUTSTATIC;
                    add(line, field ? policy.field(handle.getOwner(), handle.getName())
                            : policy.method(handle.getOwner(), handle.getName(), handle.getDesc(), false));
                } else if (value instanceof ConstantDynamic dynamic) {
                    Object[] arguments = new Object[dynamic.getBootstrapMethodArgumentCount()];
                    for (int i = 0; i < arguments.length; i++) {
                        arguments[i] = dynamic.getBootstrapMethodArgument(i);
                    }
                    bootstrap(dynamic.getBootstrapMethod(), arguments);
                }
            }
        }
    }
}
