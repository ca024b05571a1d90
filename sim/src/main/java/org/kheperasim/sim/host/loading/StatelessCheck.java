package org.kheperasim.sim.host.loading;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.FieldVisitor;
import org.objectweb.asm.Handle;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * Does a controller's code keep no state of its own outside its objects? Then one definition of its
 * classes can serve every robot of every run in the process: a static field is each robot's own
 * (docs/controller-rules.md), and a controller whose statics are constants has nothing to keep
 * apart. Sharing the classes lets the JIT compile them once, instead of again for every robot of
 * every run.
 *
 * <p>Deliberately conservative: a class graph passes only when every static field of the
 * controller's own classes is {@code final} and holds a primitive, a string, a boxed number, one of
 * its own enum's constants, or an array that is only ever read ({@code W[i]}, {@code W.length},
 * {@code W[i][j]}, {@code W.clone()}: the array reference is used by nothing else); when a static initializer only
 * builds such constants; when an enum's fields are final primitives or strings; and when no static
 * method is {@code synchronized}. Anything else (a static counter, a static list, an array handed to
 * a method) keeps today's loading: classes of its own for each robot.
 */
final class StatelessCheck implements Opcodes {
    private final Function<String, byte[]> own;
    /** The classes of the controller's own reached so far, with their class files. */
    private final Map<String, byte[]> closure = new LinkedHashMap<>();
    /** Per own class: its static fields of array type (read-only allowed). */
    private final Map<String, Set<String>> arrayStatics = new HashMap<>();
    private String why;

    private StatelessCheck(Function<String, byte[]> own) {
        this.own = own;
    }

    /**
     * What the check found: the class files of the controller's own classes it reaches, and why it is not stateless
     * (null: it is).
     */
    record Result(Map<String, byte[]> closure, String why) {
        boolean stateless() {
            return why == null;
        }
    }

    /**
     * @param start the controller class (internal name)
     * @param own the class file of a class of the controller's own (found on its classpath), or null for any other
     * @return the classes reached and the verdict
     */
    static Result check(String start, Function<String, byte[]> own) {
        StatelessCheck c = new StatelessCheck(own);
        Deque<String> todo = new ArrayDeque<>();
        todo.add(start);
        Set<String> seen = new HashSet<>();
        // First every class's static fields (a method may read another class's), then the code.
        while (!todo.isEmpty()) {
            String name = todo.poll();
            if (!seen.add(name)) {
                continue;
            }
            byte[] bytes = own.apply(name);
            if (bytes == null) {
                continue;
            }
            c.closure.put(name, bytes);
            try {
                ClassReader r = new ClassReader(bytes);
                for (String ref : references(r)) {
                    todo.add(ref);
                }
                c.fields(name, r);
            } catch (RuntimeException malformed) { // ASM's way to say so: then it is not shared
                c.fail(name, "its class file cannot be read");
            }
        }
        for (Map.Entry<String, byte[]> e : c.closure.entrySet()) {
            if (c.why == null) {
                try {
                    c.code(e.getKey(), new ClassReader(e.getValue()));
                } catch (RuntimeException malformed) {
                    c.fail(e.getKey(), "its class file cannot be read");
                }
            }
        }
        return new Result(c.closure, c.why);
    }

    private void fail(String className, String reason) {
        if (why == null) {
            why = className.replace('/', '.') + ": " + reason;
        }
    }

    /** The class names a class file refers to (its constant pool's classes, and the types in descriptors). */
    private static Set<String> references(ClassReader r) {
        Set<String> out = new HashSet<>();
        char[] buf = new char[r.getMaxStringLength()];
        for (int i = 1; i < r.getItemCount(); i++) {
            int at = r.getItem(i);
            if (at > 0 && r.readByte(at - 1) == 7) { // CONSTANT_Class
                String n = r.readUTF8(at, buf);
                out.add(n.startsWith("[") ? Type.getType(n).getElementType().getInternalName() : n);
            }
        }
        return out;
    }

    private void fields(String className, ClassReader r) {
        boolean isEnum = (r.getAccess() & ACC_ENUM) != 0;
        Set<String> arrays = new HashSet<>();
        arrayStatics.put(className, arrays);
        r.accept(new ClassVisitor(ASM9) {
            @Override
            public FieldVisitor visitField(int access, String name, String descriptor, String signature, Object value) {
                Type t = Type.getType(descriptor);
                boolean isStatic = (access & ACC_STATIC) != 0;
                boolean isFinal = (access & ACC_FINAL) != 0;
                if (isStatic) {
                    if (!isFinal) {
                        fail(className, "static field " + name + " is not final");
                    } else if (t.getSort() == Type.ARRAY) {
                        arrays.add(name);
                    } else if (t.getSort() == Type.OBJECT && !immutable(t.getInternalName())
                            && !(isEnum && t.getInternalName().equals(className))) {
                        fail(className, "static field " + name + " holds a " + t.getClassName());
                    }
                } else if (isEnum && !(isFinal && (t.getSort() != Type.OBJECT && t.getSort() != Type.ARRAY
                        || immutable(t.getInternalName())))) {
                    fail(className, "enum field " + name + " is not a final primitive or string");
                }
                return null;
            }
        }, ClassReader.SKIP_CODE | ClassReader.SKIP_DEBUG | ClassReader.SKIP_FRAMES);
    }

    private static boolean immutable(String internalName) {
        return switch (internalName) {
            case "java/lang/String", "java/lang/Integer", "java/lang/Long", "java/lang/Double", "java/lang/Float",
                    "java/lang/Short", "java/lang/Byte", "java/lang/Character", "java/lang/Boolean" -> true;
            default -> false;
        };
    }

    private void code(String className, ClassReader r) {
        boolean isEnum = (r.getAccess() & ACC_ENUM) != 0;
        r.accept(new ClassVisitor(ASM9) {
            @Override
            public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                    String[] exceptions) {
                if ((access & ACC_STATIC) != 0 && (access & ACC_SYNCHRONIZED) != 0) {
                    fail(className, "static method " + name + " is synchronized (its lock would be every robot's)");
                }
                // A static initializer runs once for all robots once shared, an enum's constructor with it.
                boolean init = name.equals("<clinit>") || isEnum && name.equals("<init>");
                boolean values = isEnum && name.equals("values");
                return new Reads(className, name, init, values);
            }
        }, ClassReader.SKIP_DEBUG | ClassReader.SKIP_FRAMES);
    }

    /** Follows the references to read-only static arrays on the operand stack: read, never handed on. */
    private final class Reads extends MethodVisitor {
        private final String className;
        private final String method;
        private final boolean init;
        private final boolean values;
        /** Read-only arrays (and parts of them) on the stack that an element read or a length must consume. */
        private int pending;
        private boolean loadedThis;

        Reads(String className, String method, boolean init, boolean values) {
            super(ASM9);
            this.className = className;
            this.method = method;
            this.init = init;
            this.values = values;
        }

        private void escape(String what) {
            if (pending > 0) {
                fail(className, "in " + method + ", a static array is " + what + " (it could be changed)");
            }
        }

        private boolean readOnlyArray(String owner, String name) {
            Set<String> a = arrayStatics.get(owner);
            return a != null && a.contains(name);
        }

        @Override
        public void visitFieldInsn(int opcode, String owner, String name, String descriptor) {
            boolean ownField = arrayStatics.containsKey(owner);
            if (opcode == GETSTATIC && readOnlyArray(owner, name) && !init) {
                pending++;
                loadedThis = false;
                return;
            }
            if (opcode == PUTSTATIC && ownField && !init) {
                fail(className, "in " + method + ", static field " + name + " is written");
            }
            if (opcode == GETFIELD && loadedThis && Type.getType(descriptor).getSort() != Type.OBJECT
                    && Type.getType(descriptor).getSort() != Type.ARRAY) {
                loadedThis = false;
                return; // this.index: an int for an element read
            }
            loadedThis = false;
            escape("next to a field access");
        }

        @Override
        public void visitInsn(int opcode) {
            loadedThis = false;
            if (pending > 0) {
                if (opcode >= IALOAD && opcode <= SALOAD) {
                    // An element of a read-only array: an inner array (AALOAD) is read-only too.
                    pending--;
                    if (opcode == AALOAD) {
                        pending++;
                    }
                    return;
                }
                if (opcode == ARRAYLENGTH) {
                    pending--;
                    return;
                }
                if (pureArithmetic(opcode)) {
                    return;
                }
                escape("used by another instruction");
            }
            if (opcode == MONITORENTER) {
                // A shared class's monitors would be every robot's (its loader's stand-ins too, see Monitors).
                fail(className, "in " + method + ", a lock is taken on an object that may be shared");
            }
        }

        @Override
        public void visitIntInsn(int opcode, int operand) {
            loadedThis = false;
            if (opcode == NEWARRAY) {
                escape("next to a new array");
            }
        }

        @Override
        public void visitVarInsn(int opcode, int var) {
            if (pending > 0 && opcode == ALOAD && var == 0) {
                loadedThis = true;
                return;
            }
            loadedThis = false;
            if (opcode == ILOAD || opcode == LLOAD || opcode == FLOAD || opcode == DLOAD) {
                return;
            }
            escape("next to a local variable's object");
        }

        @Override
        public void visitTypeInsn(int opcode, String type) {
            loadedThis = false;
            escape("next to " + type);
        }

        @Override
        public void visitMethodInsn(int opcode, String owner, String name, String descriptor, boolean isInterface) {
            loadedThis = false;
            if (pending > 0 && name.equals("clone") && owner.startsWith("[")) {
                pending--; // a copy of the array (an enum's values()): the array itself stays as it was
                return;
            }
            escape("passed to " + owner.replace('/', '.') + "." + name);
            boolean constants = owner.equals(className) && (name.equals("<init>") || name.equals("$values"))
                    || immutable(owner) && name.equals("valueOf")
                    || owner.equals("java/lang/Enum") && name.equals("<init>");
            if (init && !constants) {
                fail(className, "its static initializer calls " + owner.replace('/', '.') + "." + name
                        + " (shared, it would run once for all robots, not once for each)");
            }
        }

        @Override
        public void visitInvokeDynamicInsn(String name, String descriptor, Handle bsm, Object... args) {
            loadedThis = false;
            escape("captured by a lambda");
            if (init) {
                fail(className, "its static initializer makes a lambda or a string");
            }
        }

        @Override
        public void visitJumpInsn(int opcode, Label label) {
            loadedThis = false;
            escape("left on the stack across a jump");
        }

        @Override
        public void visitLdcInsn(Object value) {
            loadedThis = false;
            if (value instanceof Type || value instanceof Handle) {
                escape("next to a class constant");
            }
        }

        @Override
        public void visitIincInsn(int var, int increment) {
            loadedThis = false;
        }

        @Override
        public void visitTableSwitchInsn(int min, int max, Label dflt, Label... labels) {
            loadedThis = false;
            escape("left on the stack across a switch");
        }

        @Override
        public void visitLookupSwitchInsn(Label dflt, int[] keys, Label[] labels) {
            loadedThis = false;
            escape("left on the stack across a switch");
        }

        @Override
        public void visitMultiANewArrayInsn(String descriptor, int numDimensions) {
            loadedThis = false;
            escape("next to a new array");
        }

        @Override
        public void visitEnd() {
            if (pending > 0) {
                fail(className, "in " + method + ", a static array is used in a way the check does not follow");
            }
        }
    }

    /** Instructions that only compute with numbers on the stack (an index, a value read). */
    private static boolean pureArithmetic(int opcode) {
        return opcode >= ICONST_M1 && opcode <= DCONST_1 || opcode >= IADD && opcode <= LXOR
                || opcode >= I2L && opcode <= I2S
                || opcode >= LCMP && opcode <= DCMPG;
    }
}
