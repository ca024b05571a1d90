package org.kheperasim.sim.host.loading;

import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.FieldVisitor;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;

/**
 * The class hierarchy as one {@link ControllerClassLoader} sees it, and where the JVM would find a
 * member: classes the loader defines itself ("local" ones) are read from their class files, never
 * loaded; every other class (the Java platform, the simulator) is looked up without initialising it
 * in the parent loader. Answers are cached, so each class is read at most once.
 *
 * <p>Members are resolved as the JVM resolves them (JVMS 5.4.3): a method in the class and its
 * superclasses, then in the maximally specific superinterfaces; an interface method also among
 * {@code Object}'s public ones; a field in the class, its superinterfaces, then its superclass. So
 * {@code ArrayList.stream()} is {@code Collection.stream()}, and {@code stop()} called on a
 * student's {@code Thread} subclass is {@code Thread.stop()}.
 */
final class ClassHierarchy implements HierarchyLookup {
    private static final String OBJECT = "java/lang/Object";
    private static final String THREAD = "java/lang/Thread";
    private static final Set<String> OBJECT_PUBLIC = Set.of("equals(Ljava/lang/Object;)Z", "hashCode()I",
            "toString()Ljava/lang/String;", "getClass()Ljava/lang/Class;", "notify()V", "notifyAll()V", "wait()V",
            "wait(J)V", "wait(JI)V");

    /** What the hierarchy needs to know of one class. */
    private record ClassFacts(boolean local, boolean isInterface, String superName, List<String> interfaces,
            Set<String> methods, Set<String> fields) {
        /** Found nowhere, or unreadable: it tells nothing. */
        static final ClassFacts MISSING = new ClassFacts(false, false, null, List.of(), Set.of(), Set.of());
    }

    /**
     * What reflection told of the parent's classes, shared by every loader with that parent: the
     * facts of a platform class never change, and a run of many robots makes a loader per robot.
     */
    private static final Map<ClassLoader, Map<String, ClassFacts>> PARENT_FACTS =
            java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());

    private final Function<String, byte[]> localClassFile;
    private final ClassLoader parent;
    private final Map<String, ClassFacts> parentFacts;
    private final Map<String, ClassFacts> facts = new ConcurrentHashMap<>();
    private final Map<String, List<String>> methodAnswers = new ConcurrentHashMap<>();

    /**
     * @param localClassFile the class file that the loader would define for an internal class
     *     name, or null when the class comes from the parent (or nowhere)
     * @param parent where every other class is looked up
     */
    ClassHierarchy(Function<String, byte[]> localClassFile, ClassLoader parent) {
        this.localClassFile = localClassFile;
        this.parent = parent;
        this.parentFacts = PARENT_FACTS.computeIfAbsent(parent, p -> new ConcurrentHashMap<>());
    }

    @Override
    public boolean resolvesToThread(String owner, String name, String descriptor) {
        return List.of(THREAD).equals(declaringClasses(owner, name, descriptor));
    }

    @Override
    public String declaringClass(String owner, String name, String descriptor) {
        List<String> found = declaringClasses(owner, name, descriptor);
        return found.size() == 1 ? found.get(0) : null;
    }

    /**
     * @return whether the loader defines the class itself (from the classpath, or a class file resource of the parent)
     */
    boolean isLocal(String internalName) {
        return facts(internalName).local();
    }

    /** @return whether the class can be found at all, locally or in the parent */
    boolean exists(String internalName) {
        return facts(internalName) != ClassFacts.MISSING;
    }

    /**
     * Where the JVM finds the method {@code owner.name descriptor}: one class, or the maximally
     * specific superinterfaces that declare it (several only when no class does).
     *
     * @return internal names; empty when it is found nowhere (the call would fail on its own)
     */
    List<String> declaringClasses(String owner, String name, String descriptor) {
        String key = owner + '.' + name + descriptor;
        List<String> answer = methodAnswers.get(key);
        if (answer == null) {
            answer = resolveMethod(owner, name + descriptor, name.equals("<init>"));
            methodAnswers.putIfAbsent(key, answer);
        }
        return answer;
    }

    private List<String> resolveMethod(String owner, String method, boolean constructor) {
        ClassFacts f = facts(owner);
        if (f == ClassFacts.MISSING) {
            return List.of();
        }
        if (constructor || f.methods().contains(method)) {
            return f.methods().contains(method) ? List.of(owner) : List.of();
        }
        List<String> chain = new ArrayList<>();
        if (f.isInterface()) {
            if (OBJECT_PUBLIC.contains(method)) {
                return List.of(OBJECT);
            }
            chain.add(owner);
        } else {
            Set<String> seen = new HashSet<>();
            for (String c = owner; c != null && seen.add(c); c = facts(c).superName()) {
                ClassFacts cf = facts(c);
                if (cf == ClassFacts.MISSING) {
                    return List.of();
                }
                if (cf.methods().contains(method)) {
                    return List.of(c);
                }
                chain.add(c);
            }
        }
        return maximallySpecific(superinterfaces(chain), method);
    }

    /** Every interface the classes (or interfaces) implement or extend, directly or not, without themselves. */
    private Set<String> superinterfaces(List<String> types) {
        Set<String> found = new LinkedHashSet<>();
        Deque<String> open = new ArrayDeque<>();
        types.forEach(t -> open.addAll(facts(t).interfaces()));
        while (!open.isEmpty()) {
            String i = open.removeFirst();
            if (found.add(i)) {
                open.addAll(facts(i).interfaces());
            }
        }
        return found;
    }

    private List<String> maximallySpecific(Set<String> interfaces, String method) {
        List<String> declaring = interfaces.stream().filter(i -> facts(i).methods().contains(method)).toList();
        return declaring.stream()
                .filter(i -> declaring.stream().noneMatch(other -> !other.equals(i) && isSubtypeOf(other, i)))
                .toList();
    }

    /**
     * Where the JVM finds the field {@code owner.name}.
     *
     * @return the internal name of the class or interface that declares it, or null when none does
     */
    String declaringField(String owner, String name) {
        return declaringField(owner, name, new HashSet<>());
    }

    private String declaringField(String owner, String name, Set<String> seen) {
        ClassFacts f = facts(owner);
        if (f == ClassFacts.MISSING || !seen.add(owner)) {
            return null;
        }
        if (f.fields().contains(name)) {
            return owner;
        }
        for (String i : f.interfaces()) {
            String found = declaringField(i, name, seen);
            if (found != null) {
                return found;
            }
        }
        return f.superName() == null ? null : declaringField(f.superName(), name, seen);
    }

    /** @return whether {@code type} is {@code ancestor} or extends or implements it, directly or not */
    boolean isSubtypeOf(String type, String ancestor) {
        Set<String> seen = new HashSet<>();
        Deque<String> open = new ArrayDeque<>(List.of(type));
        while (!open.isEmpty()) {
            String t = open.removeFirst();
            if (t.equals(ancestor)) {
                return true;
            }
            if (seen.add(t)) {
                ClassFacts f = facts(t);
                if (f.superName() != null) {
                    open.add(f.superName());
                }
                open.addAll(f.interfaces());
            }
        }
        return false;
    }

    private ClassFacts facts(String internalName) {
        return facts.computeIfAbsent(internalName, this::read);
    }

    private ClassFacts read(String internalName) {
        byte[] classFile = localClassFile.apply(internalName);
        return classFile != null ? fromClassFile(classFile)
                : parentFacts.computeIfAbsent(internalName, this::fromParent);
    }

    /** Superclass, interfaces and declared members from a class file the loader would define. */
    private static ClassFacts fromClassFile(byte[] classFile) {
        try {
            ClassReader reader = new ClassReader(classFile);
            Set<String> methods = new HashSet<>();
            Set<String> fields = new HashSet<>();
            reader.accept(new ClassVisitor(Opcodes.ASM9) {
                @Override
                public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                        String[] exceptions) {
                    methods.add(name + descriptor);
                    return null;
                }

                @Override
                public FieldVisitor visitField(int access, String name, String descriptor,
                        String signature, Object value) {
                    fields.add(name);
                    return null;
                }
            }, ClassReader.SKIP_CODE | ClassReader.SKIP_DEBUG | ClassReader.SKIP_FRAMES);
            return new ClassFacts(true, (reader.getAccess() & Opcodes.ACC_INTERFACE) != 0, reader.getSuperName(),
                    List.of(reader.getInterfaces()), Set.copyOf(methods), Set.copyOf(fields));
        } catch (RuntimeException e) {
            // A malformed class file: loading it reports the failure; here it tells nothing, and is
            // still the loader's own, so nothing it names is taken for a class of the platform.
            return new ClassFacts(true, false, null, List.of(), Set.of(), Set.of());
        }
    }

    /**
     * The same facts of a class of the parent loader, by reflection (without initialising it). A
     * class that cannot be found or linked tells nothing: a use of it would fail on its own.
     */
    private ClassFacts fromParent(String internalName) {
        if (internalName.contains(".") || internalName.startsWith("[")) {
            return ClassFacts.MISSING;
        }
        try {
            Class<?> type = Class.forName(internalName.replace('/', '.'), false, parent);
            Set<String> methods = new HashSet<>();
            for (Method m : type.getDeclaredMethods()) {
                methods.add(m.getName() + Type.getMethodDescriptor(m));
            }
            for (Constructor<?> c : type.getDeclaredConstructors()) {
                methods.add("<init>" + Type.getConstructorDescriptor(c));
            }
            Set<String> fields = new HashSet<>();
            for (Field f : type.getDeclaredFields()) {
                fields.add(f.getName());
            }
            Class<?> superclass = type.getSuperclass();
            List<String> interfaces = Arrays.stream(type.getInterfaces()).map(Type::getInternalName).toList();
            return new ClassFacts(false, type.isInterface(),
                    superclass == null ? null : Type.getInternalName(superclass),
                    interfaces, Set.copyOf(methods), Set.copyOf(fields));
        } catch (ClassNotFoundException | LinkageError e) {
            return ClassFacts.MISSING;
        }
    }
}
