package org.kheperasim.sim.host.loading;

import java.util.Arrays;
import java.util.List;
import java.util.function.BiPredicate;
import java.util.stream.Collectors;
import org.objectweb.asm.Type;

/**
 * What untrusted controller code may use: a class of its own, or a class or member of the Java
 * platform and the simulator that the {@link Allowlist} allows. Everything else is refused when the
 * class is loaded (Java's SecurityManager is gone, so the check is made on the bytecode): every
 * call, field access, type use, class constant, method handle and bootstrap method, and every
 * superclass and interface. A member is looked up first where the JVM would find it
 * ({@link ClassHierarchy}), so a method inherited from the platform is judged as the platform's,
 * whatever class the call names.
 *
 * <p>A list of forbidden calls always misses a door: the JDK does forbidden things on its caller's
 * behalf (bean scripting, JMX, XML entities, file-name constructors, preferences). An allowlist
 * names only what is known to stay inside the run.
 */
final class ControllerPolicy {
    /** Where a refusal sends the student. */
    static final String DOCS = "docs/controller-rules.md lists what controller code may use";

    /** The rule for a use that no entry of the refused group explains. */
    static final String NOT_ALLOWED = "it is not on the allowlist of what untrusted controller code may use (computing,"
            + " collections, text, printing, its own resources, its own threads and the robot's API); remove the use,"
            + " or run a controller you trust with --trusted";

    /**
     * A use refused.
     *
     * @param verb how the class uses it ({@code uses}, {@code extends}, {@code declares})
     * @param what the class or member, as a student reads it
     * @param why the rule
     */
    record Refusal(String verb, String what, String why) {
    }

    private final Allowlist list;
    private final ClassHierarchy hierarchy;
    private final BiPredicate<String, String> isSubclass;

    /**
     * @param list what is allowed
     * @param hierarchy the classes as the loader sees them
     */
    ControllerPolicy(Allowlist list, ClassHierarchy hierarchy) {
        this.list = list;
        this.hierarchy = hierarchy;
        this.isSubclass = (type, ancestor) -> hierarchy.isSubtypeOf(type.replace('.', '/'), ancestor.replace('.', '/'));
    }

    /**
     * @param internalName a type named by a cast, an instanceof, a {@code new}, an array creation or
     *     a class constant (an internal name, or an array descriptor)
     * @return the refusal, or null when it is allowed
     */
    Refusal type(String internalName) {
        String element = elementType(internalName);
        if (element == null || isOwn(element)) {
            return null;
        }
        String binary = binary(element);
        return list.allowsType(binary, isSubclass) ? null : new Refusal("uses", binary, why(binary, null, null));
    }

    /**
     * @param verb {@code extends} or {@code implements}
     * @return the refusal of a superclass or interface, or null when it may be extended or implemented
     */
    Refusal supertype(String internalName, String verb) {
        Refusal r = type(internalName);
        return r == null ? null : new Refusal(verb, r.what(), r.why());
    }

    /**
     * @param owner the class a call or method handle names
     * @param asBootstrap the method is named as a bootstrap method (of an invokedynamic or a dynamic
     *     constant)
     * @return the refusal, or null when it is allowed
     */
    Refusal method(String owner, String name, String descriptor, boolean asBootstrap) {
        if (owner.startsWith("[")) {
            return type(owner); // clone() of an array
        }
        List<String> declaring = hierarchy.declaringClasses(owner, name, descriptor);
        if (declaring.isEmpty()) {
            if (isOwn(owner)) {
                return null; // found nowhere: the call fails on its own
            }
            declaring = List.of(owner);
        }
        List<String> parameters = Arrays.stream(Type.getArgumentTypes(descriptor)).map(Type::getClassName).toList();
        for (String d : declaring) {
            if (hierarchy.isLocal(d)) {
                continue;
            }
            String binary = binary(d);
            if (!list.allowsMember(binary, name, parameters, asBootstrap, isSubclass)) {
                String what = (name.equals("<init>") ? "new " + binary : binary + "." + name) + "("
                        + parameters.stream().map(ControllerPolicy::simple).collect(Collectors.joining(", ")) + ")";
                return new Refusal("uses", what + through(owner, d), why(binary, name, parameters));
            }
        }
        return null;
    }

    /** @return the refusal of a field access, or null when it is allowed */
    Refusal field(String owner, String name) {
        String declaring = hierarchy.declaringField(owner, name);
        if (declaring == null) {
            if (isOwn(owner)) {
                return null;
            }
            declaring = owner;
        }
        if (hierarchy.isLocal(declaring)) {
            return null;
        }
        String binary = binary(declaring);
        return list.allowsMember(binary, name, null, false, isSubclass) ? null
                : new Refusal("uses", binary + "." + name + through(owner, declaring), why(binary, name, null));
    }

    /** @return the refusal of a class that declares a finalizer */
    Refusal finalizer() {
        return new Refusal("declares", "finalize()", why("java.lang.Object", "finalize", List.of()));
    }

    /**
     * @param className the class being checked (internal name)
     * @param source its source file, or null
     * @param line the source line, or 0 or less when unknown
     * @return the error to throw: one line naming the student's file and line, the use and the rule
     */
    static ControllerPolicyError error(String className, String source, int line, Refusal r) {
        String where = (source != null ? source : className.replace('/', '.')) + (line > 0 ? ":" + line : "");
        return new ControllerPolicyError(where + ": " + r.verb() + " " + r.what() + ": " + r.why() + " (" + DOCS + ")");
    }

    /** A class the controller's loader defines, or one found nowhere (its use fails on its own when it runs). */
    /**
     * The controller's own classes, and a class found nowhere outside the Java platform's packages
     * (a class of its own it left out: using it fails on its own). A platform class this JVM lacks
     * (one a newer JDK removed, such as {@code javax.management.loading.MLet}) is judged by the
     * allowlist like any other, so that a controller is refused alike on every JDK.
     */
    private boolean isOwn(String internalName) {
        return hierarchy.isLocal(internalName) || !hierarchy.exists(internalName) && !isPlatform(internalName);
    }

    private static boolean isPlatform(String internalName) {
        for (String p : PLATFORM_PACKAGES) {
            if (internalName.startsWith(p)) {
                return true;
            }
        }
        return false;
    }

    /** The packages of the Java SE and JDK modules, and JavaFX (internal names). */
    private static final List<String> PLATFORM_PACKAGES = List.of("java/", "javax/", "jdk/", "sun/", "com/sun/",
            "org/w3c/", "org/xml/", "org/ietf/", "netscape/", "javafx/");

    private String why(String binary, String member, List<String> parameters) {
        String reason = list.refusalReason(binary, member, parameters, isSubclass);
        return reason != null ? reason : NOT_ALLOWED;
    }

    private static String through(String owner, String declaring) {
        return owner.equals(declaring) ? "" : " (called through " + binary(owner) + ")";
    }

    /** @return the class an array type is made of, or null for a primitive array */
    private static String elementType(String internalName) {
        if (!internalName.startsWith("[")) {
            return internalName;
        }
        Type element = Type.getType(internalName).getElementType();
        return element.getSort() == Type.OBJECT ? element.getInternalName() : null;
    }

    private static String binary(String internalName) {
        return internalName.replace('/', '.');
    }

    /** {@code java.lang.String} as {@code String}, {@code java.util.Map$Entry[]} as {@code Map$Entry[]}. */
    private static String simple(String binaryName) {
        return binaryName.substring(binaryName.lastIndexOf('.') + 1);
    }
}
