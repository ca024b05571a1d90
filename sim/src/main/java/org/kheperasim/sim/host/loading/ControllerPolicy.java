package org.kheperasim.sim.host.loading;

import java.util.List;

/**
 * What controller code may not touch: a controller runs untrusted, in grading and in headless runs
 * alike, so the loader refuses a class that reaches for the machine or for the simulator behind the
 * API. The check is made on the bytecode at load time (Java 17's SecurityManager is deprecated),
 * on every call, field access, type use, class constant and method handle, so a forbidden method
 * cannot be reached by a method reference either; reflection and method-handle lookups, which could
 * reach anything by name, are refused as such.
 *
 * <p>Allowed: the student API, the Java library for computing (collections, maths, strings,
 * {@code java.time}, threads, which the simulator contains), printing to {@code System.out},
 * Swing and AWT for a controller's own debug window.
 */
final class ControllerPolicy {
    /** A forbidden group of classes or members, and why. */
    private record Rule(String ownerPrefix, List<String> members, String why) {
        boolean matches(String owner, String member) {
            if (!owner.startsWith(ownerPrefix)) {
                return false;
            }
            if (members.isEmpty()) {
                return true;
            }
            return member != null && members.stream().anyMatch(m -> m.endsWith("*") ? member.startsWith(m.substring(0, m.length() - 1)) : m.equals(member));
        }
    }

    private static final String FILES = "controllers may not touch files";
    private static final String NETWORK = "controllers may not open network connections";
    private static final String PROCESSES = "controllers may not start processes";
    private static final String NATIVE = "controllers may not load native code or use internal JDK classes";
    private static final String LOADERS = "controllers may not define or load classes themselves";
    private static final String REFLECTION = "controllers may not use reflection to reach members by name";
    private static final String SIMULATOR = "controllers see only the student API (org.kheperasim.api), not the simulator";
    private static final String STREAMS = "controllers may not replace the standard streams or system properties";

    private static final List<Rule> RULES = List.of(
            new Rule("java/io/File", List.of(), FILES),
            new Rule("java/io/RandomAccessFile", List.of(), FILES),
            new Rule("java/nio/file/", List.of(), FILES),
            new Rule("java/nio/channels/", List.of(), FILES + " or the network"),
            new Rule("java/net/", List.of(), NETWORK),
            new Rule("javax/net/", List.of(), NETWORK),
            new Rule("java/lang/ProcessBuilder", List.of(), PROCESSES),
            new Rule("java/lang/ProcessHandle", List.of(), PROCESSES),
            new Rule("java/lang/Runtime", List.of("exec", "load", "loadLibrary"), PROCESSES + " or native code"),
            new Rule("java/lang/System", List.of("load", "loadLibrary", "mapLibraryName"), NATIVE),
            new Rule("java/lang/System", List.of("setOut", "setErr", "setIn", "setProperty", "setProperties",
                    "clearProperty", "setSecurityManager"), STREAMS),
            new Rule("sun/", List.of(), NATIVE),
            new Rule("jdk/internal/", List.of(), NATIVE),
            new Rule("java/lang/ClassLoader", List.of(), LOADERS),
            new Rule("java/lang/Class", List.of("forName", "newInstance", "getClassLoader"), REFLECTION + " or load classes"),
            new Rule("java/lang/reflect/Method", List.of("invoke", "setAccessible", "trySetAccessible"), REFLECTION),
            new Rule("java/lang/reflect/Field", List.of("get*", "set*", "trySetAccessible"), REFLECTION),
            new Rule("java/lang/reflect/Constructor", List.of("newInstance", "setAccessible", "trySetAccessible"), REFLECTION),
            new Rule("java/lang/reflect/AccessibleObject", List.of("setAccessible", "trySetAccessible"), REFLECTION),
            new Rule("java/lang/reflect/Proxy", List.of(), REFLECTION),
            new Rule("java/lang/invoke/MethodHandles", List.of("privateLookupIn", "reflectAs"), REFLECTION),
            new Rule("java/lang/invoke/MethodHandles$Lookup", List.of("find*", "unreflect*", "in", "defineClass",
                    "defineHiddenClass", "accessClass", "ensureInitialized"), REFLECTION),
            new Rule("org/kheperasim/sim/", List.of(), SIMULATOR),
            new Rule("org/kheperasim/link/", List.of(), SIMULATOR));

    private ControllerPolicy() {
    }

    /**
     * @param owner internal name of the class used
     * @param member the member's name, or null for a use of the type itself
     * @return why the use is refused, or null when it is allowed
     */
    static String refusal(String owner, String member) {
        for (Rule r : RULES) {
            if (r.matches(owner, member)) {
                // A use of the type alone (a local variable's type, a cast) is harmless unless every member is forbidden.
                if (member == null && !r.members().isEmpty()) {
                    return null;
                }
                return r.why();
            }
        }
        return null;
    }

    /**
     * @param className the class being loaded (internal name)
     * @param source its source file, or null
     * @param line the source line, or -1
     * @param owner the class used
     * @param member the member used, or null
     * @param why the rule
     * @return the error to throw
     */
    static ControllerPolicyError error(String className, String source, int line, String owner, String member,
            String why) {
        String where = (source != null ? source : className.replace('/', '.')) + (line > 0 ? ":" + line : "");
        String what = owner.replace('/', '.') + (member != null ? "." + member : "");
        return new ControllerPolicyError(where + ": uses " + what + ": " + why + " (the simulator refuses it so that"
                + " a run cannot harm the machine or fake a result; remove the call)");
    }
}
