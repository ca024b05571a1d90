package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.WildcardType;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The testing API is one package a test needs and nothing else: its public types, methods and fields name
 * only its own types, Java's and JUnit's (never the simulator's internals), and it holds no Swing or AWT.
 */
class ApiShapeTest {
    /** @return the class files of the API (the main classes, not the tests) */
    private static List<Path> classFiles() throws IOException, URISyntaxException {
        Path dir = Path.of(Run.class.getProtectionDomain().getCodeSource().getLocation().toURI()).resolve("org/kheperasim/testing");
        try (Stream<Path> files = Files.list(dir)) {
            List<Path> out = files.filter(f -> f.toString().endsWith(".class")).sorted().toList();
            assertTrue(out.size() > 10, "the API's classes in " + dir);
            return out;
        }
    }

    @Test
    void publicSignaturesNameOnlyThisPackageJavaAndJUnit() throws Exception {
        List<String> leaks = new ArrayList<>();
        for (Path file : classFiles()) {
            String name = file.getFileName().toString().replaceFirst("\\.class$", "");
            Class<?> type = Class.forName("org.kheperasim.testing." + name);
            if (!Modifier.isPublic(type.getModifiers())) {
                continue;
            }
            for (Method m : type.getDeclaredMethods()) {
                if (Modifier.isPublic(m.getModifiers())) {
                    check(type.getSimpleName() + "." + m.getName(), m.getGenericReturnType(), leaks);
                    for (Type p : m.getGenericParameterTypes()) {
                        check(type.getSimpleName() + "." + m.getName(), p, leaks);
                    }
                    for (Type e : m.getGenericExceptionTypes()) {
                        check(type.getSimpleName() + "." + m.getName(), e, leaks);
                    }
                }
            }
            for (Constructor<?> k : type.getDeclaredConstructors()) {
                if (Modifier.isPublic(k.getModifiers())) {
                    for (Type p : k.getGenericParameterTypes()) {
                        check(type.getSimpleName() + "()", p, leaks);
                    }
                }
            }
            for (Field f : type.getDeclaredFields()) {
                if (Modifier.isPublic(f.getModifiers())) {
                    check(type.getSimpleName() + "." + f.getName(), f.getGenericType(), leaks);
                }
            }
        }
        assertEquals(List.of(), leaks, "public signatures that name a type a test would have to import from elsewhere");
    }

    /** A class that uses a type names it in its constant pool, so no AWT or Swing name there means no use of them. */
    @Test
    void itHoldsNoSwingOrAwt() throws Exception {
        List<String> uses = new ArrayList<>();
        for (Path file : classFiles()) {
            String bytes = new String(Files.readAllBytes(file), StandardCharsets.ISO_8859_1);
            if (bytes.contains("java/awt/") || bytes.contains("javax/swing/")) {
                uses.add(file.getFileName().toString());
            }
        }
        assertEquals(List.of(), uses, "tests run headless, and the testing API needs no window");
    }

    private static void check(String where, Type t, List<String> leaks) {
        if (t instanceof ParameterizedType p) {
            check(where, p.getRawType(), leaks);
            for (Type a : p.getActualTypeArguments()) {
                check(where, a, leaks);
            }
        } else if (t instanceof WildcardType w) {
            for (Type b : w.getUpperBounds()) {
                check(where, b, leaks);
            }
        } else if (t instanceof Class<?> c) {
            Class<?> e = c.isArray() ? c.getComponentType() : c;
            String n = e.getName();
            if (!e.isPrimitive() && !n.startsWith("java.") && !n.startsWith("org.kheperasim.testing.")
                    && !n.startsWith("org.junit.") && !n.startsWith("org.opentest4j.")) {
                leaks.add(where + ": " + n);
            }
        }
    }
}
