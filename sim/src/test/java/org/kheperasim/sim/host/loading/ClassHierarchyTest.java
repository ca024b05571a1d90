package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Members are found where the JVM finds them, across the controller's own classes and the JDK's. */
class ClassHierarchyTest {
    @TempDir
    Path dir;

    private ClassHierarchy hierarchy;

    @BeforeEach
    void compileClassesOfTheControllersOwn() {
        Path classes = JavaSources.compile(dir, Map.of(
                "Names", "public class Names extends java.util.ArrayList<String> { public boolean add(String s) { return true; } }",
                "Shorter", "public interface Shorter extends java.util.Comparator<String> { default Shorter twice() { return this; } }",
                "Bot", "public class Bot extends Thread { public static final int LIMIT = 3; }"));
        hierarchy = new ClassHierarchy(name -> {
            Path f = classes.resolve(name + ".class");
            try {
                return Files.isRegularFile(f) ? Files.readAllBytes(f) : null;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }, getClass().getClassLoader());
    }

    @Test
    void methodsOfTheJdk() {
        assertEquals(List.of("java/util/ArrayList"), hierarchy.declaringClasses("java/util/ArrayList", "forEach",
                "(Ljava/util/function/Consumer;)V"), "ArrayList overrides Iterable.forEach");
        assertEquals(List.of("java/util/Collection"), hierarchy.declaringClasses("java/util/ArrayList", "stream",
                "()Ljava/util/stream/Stream;"), "a default method of a superinterface");
        assertEquals(List.of("java/util/Collection"), hierarchy.declaringClasses("java/util/List", "stream",
                "()Ljava/util/stream/Stream;"));
        assertEquals(List.of("java/lang/Object"), hierarchy.declaringClasses("java/lang/Runnable", "toString",
                "()Ljava/lang/String;"), "an interface call of Object's public method");
        assertEquals(List.of("java/util/AbstractCollection"), hierarchy.declaringClasses("java/util/ArrayList", "toString",
                "()Ljava/lang/String;"));
        assertEquals(List.of(), hierarchy.declaringClasses("java/util/ArrayList", "noSuchMethod", "()V"));
        assertEquals(List.of(), hierarchy.declaringClasses("java/util/ArrayList", "<init>", "(Ljava/lang/String;)V"),
                "constructors are not inherited");
    }

    @Test
    void methodsReachedThroughClassesOfTheControllersOwn() {
        assertEquals(List.of("Names"), hierarchy.declaringClasses("Names", "add", "(Ljava/lang/String;)Z"));
        assertEquals(List.of("Names"), hierarchy.declaringClasses("Names", "add", "(Ljava/lang/Object;)Z"), "javac's bridge");
        assertEquals(List.of("java/util/ArrayList"), hierarchy.declaringClasses("Names", "size", "()I"));
        assertEquals(List.of("java/util/Collection"), hierarchy.declaringClasses("Names", "parallelStream",
                "()Ljava/util/stream/Stream;"));
        assertEquals(List.of("java/util/Comparator"), hierarchy.declaringClasses("Shorter", "reversed",
                "()Ljava/util/Comparator;"));
        assertEquals(List.of("Shorter"), hierarchy.declaringClasses("Shorter", "twice", "()LShorter;"));
        assertEquals(List.of("java/lang/Thread"), hierarchy.declaringClasses("Bot", "stop", "()V"));
        assertTrue(hierarchy.resolvesToThread("Bot", "sleep", "(J)V"));
        assertFalse(hierarchy.resolvesToThread("Names", "sleep", "(J)V"));
        assertTrue(hierarchy.isLocal("Bot") && !hierarchy.isLocal("java/lang/Thread"));
    }

    @Test
    void fields() {
        assertEquals("Bot", hierarchy.declaringField("Bot", "LIMIT"));
        assertEquals("java/lang/Thread", hierarchy.declaringField("Bot", "MAX_PRIORITY"));
        assertEquals("java/util/AbstractList", hierarchy.declaringField("Names", "modCount"));
        assertNull(hierarchy.declaringField("Bot", "noSuchField"));
    }

    @Test
    void subtypes() {
        assertTrue(hierarchy.isSubtypeOf("Names", "java/util/Collection"));
        assertTrue(hierarchy.isSubtypeOf("java/lang/IllegalStateException", "java/lang/Throwable"));
        assertFalse(hierarchy.isSubtypeOf("java/lang/Runtime", "java/lang/Throwable"));
    }
}
