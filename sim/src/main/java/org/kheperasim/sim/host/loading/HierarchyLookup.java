package org.kheperasim.sim.host.loading;

/**
 * Answers the class-hierarchy questions {@link TimeCallRewriter} cannot answer from the class it is
 * rewriting: whether a static call made through some class reaches a method of
 * {@code java.lang.Thread}, and where a method is declared.
 *
 * <p>javac compiles an unqualified {@code sleep(100)} inside {@code class Robot extends Thread} as
 * {@code INVOKESTATIC Robot.sleep (J)V}; the JVM resolves it by searching {@code Robot} and then its
 * superclasses, so it reaches {@code Thread.sleep} unless a class on the way declares its own
 * {@code sleep(long)}.
 */
@FunctionalInterface
public interface HierarchyLookup {

    /**
     * Whether {@code INVOKESTATIC owner.name descriptor} resolves to the method that
     * {@code java.lang.Thread} itself declares.
     *
     * @param owner internal name of the call's owner class (such as {@code "pkg/Robot"}), never
     *     {@code "java/lang/Thread"}
     * @param name the method name
     * @param descriptor the method descriptor
     * @return true when {@code owner} is a subclass of {@code java.lang.Thread} and neither it nor
     *     any class between it and {@code Thread} declares {@code name} with {@code descriptor};
     *     false when that is not so or cannot be told
     */
    boolean resolvesToThread(String owner, String name, String descriptor);

    /**
     * The class or interface where the JVM finds the method {@code owner.name descriptor}.
     *
     * @return its internal name, or null when it cannot be told (or there is no single one); the
     *     default tells nothing
     */
    default String declaringClass(String owner, String name, String descriptor) {
        return null;
    }
}
