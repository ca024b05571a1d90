package org.kheperasim.sim.host.loading;

import java.lang.reflect.Method;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * The {@link HierarchyLookup} of one {@link ControllerClassLoader}: classes the loader defines
 * itself are read from their class files (superclass name and declared methods, never loading
 * them); every other class is looked up, without initialising it, in the parent loader.
 * Answers are cached, so each class file is parsed at most once.
 */
final class ClassHierarchy implements HierarchyLookup {
    private static final String THREAD = "java/lang/Thread";

    /** What a class file says about its place in the hierarchy. */
    private record ClassFacts(String superName, Set<String> methods) {
        /** A malformed class file: it tells nothing. */
        static final ClassFacts UNREADABLE = new ClassFacts(null, Set.of());
        /** The class is not defined by the loader: ask the parent. */
        static final ClassFacts IN_PARENT = new ClassFacts(null, Set.of());
    }

    private final Function<String, byte[]> localClassFile;
    private final ClassLoader parent;
    private final Map<String, ClassFacts> facts = new ConcurrentHashMap<>();
    private final Map<String, Boolean> answers = new ConcurrentHashMap<>();

    /**
     * @param localClassFile the class file that the loader would define for an internal class
     *     name, or null when the class comes from the parent (or nowhere)
     * @param parent where every other class is looked up
     */
    ClassHierarchy(Function<String, byte[]> localClassFile, ClassLoader parent) {
        this.localClassFile = localClassFile;
        this.parent = parent;
    }

    @Override
    public boolean resolvesToThread(String owner, String name, String descriptor) {
        String key = owner + '.' + name + descriptor;
        Boolean answer = answers.get(key);
        if (answer == null) {
            answer = walk(owner, name + descriptor);
            answers.putIfAbsent(key, answer);
        }
        return answer;
    }

    /** Follow superclass names from {@code owner} until Thread, a declaration of the method, or the parent. */
    private boolean walk(String owner, String method) {
        Set<String> seen = new HashSet<>();
        String name = owner;
        while (name != null && seen.add(name)) { // a cyclic hierarchy in broken class files ends the walk
            if (name.equals(THREAD)) {
                return true;
            }
            ClassFacts local = facts.computeIfAbsent(name, this::factsOf);
            if (local == ClassFacts.IN_PARENT) {
                return parentResolvesToThread(name, method);
            }
            if (local.methods().contains(method)) {
                return false;
            }
            name = local.superName();
        }
        return false;
    }

    /**
     * The same question asked of a class of the parent loader, by reflection. A class that cannot be
     * found or linked gives false: a call through it would fail on its own when it runs.
     */
    private boolean parentResolvesToThread(String internalName, String method) {
        try {
            Class<?> type = Class.forName(internalName.replace('/', '.'), false, parent);
            if (!Thread.class.isAssignableFrom(type)) {
                return false;
            }
            for (Class<?> c = type; c != Thread.class; c = c.getSuperclass()) {
                for (Method m : c.getDeclaredMethods()) {
                    if (method.equals(m.getName() + Type.getMethodDescriptor(m))) {
                        return false;
                    }
                }
            }
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }

    /** Superclass and declared methods from the loader's class file for {@code internalName}. */
    private ClassFacts factsOf(String internalName) {
        byte[] classFile = localClassFile.apply(internalName);
        if (classFile == null) {
            return ClassFacts.IN_PARENT;
        }
        try {
            ClassReader reader = new ClassReader(classFile);
            Set<String> methods = new HashSet<>();
            reader.accept(new ClassVisitor(Opcodes.ASM9) {
                @Override
                public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                        String[] exceptions) {
                    methods.add(name + descriptor);
                    return null;
                }
            }, ClassReader.SKIP_CODE | ClassReader.SKIP_DEBUG | ClassReader.SKIP_FRAMES);
            return new ClassFacts(reader.getSuperName(), methods);
        } catch (RuntimeException e) {
            return ClassFacts.UNREADABLE;
        }
    }
}
