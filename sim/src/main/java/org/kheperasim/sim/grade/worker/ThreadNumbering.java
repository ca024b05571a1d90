package org.kheperasim.sim.grade.worker;

import java.lang.reflect.Field;

/**
 * The JVM's numbering of unnamed threads ({@code Thread-0}, {@code Thread-1}, ...), put back between
 * a warm worker's runs. A controller may name no thread and then read, print or throw its thread's
 * name: in a JVM of its own the name is always the same, in a worker it would count on from the
 * earlier runs' threads and change the report. So the worker reads the counter where a graded JVM
 * starts its run, and sets it there again before each run.
 *
 * <p>The counter is a private static of {@code java.lang.Thread} (JDK 17: {@code threadInitNumber};
 * JDK 19 on: {@code Thread$ThreadNumbering.next}), reachable only with {@code --add-opens
 * java.base/java.lang=ALL-UNNAMED}, which the grader gives the worker's JVM (controllers still cannot
 * reflect: the allowlist refuses it at load). On a JDK where neither field is found, {@link #at()}
 * says so and the worker makes one run per JVM, which needs no reset.
 */
final class ThreadNumbering {
    private final Field field;

    private ThreadNumbering(Field field) {
        this.field = field;
    }

    /** @return the counter of this JVM, or null when it cannot be read and set here */
    static ThreadNumbering at() {
        for (String[] where : new String[][] {{"java.lang.Thread$ThreadNumbering", "next"},
                {"java.lang.Thread", "threadInitNumber"}}) {
            try {
                Field f = Class.forName(where[0]).getDeclaredField(where[1]);
                f.setAccessible(true);
                f.getInt(null);
                return new ThreadNumbering(f);
            } catch (ReflectiveOperationException | RuntimeException e) {
                // not this JDK's, or not opened to us
            }
        }
        return null;
    }

    /** @return the number the next unnamed thread gets */
    int next() {
        try {
            return field.getInt(null);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }

    /** @param next the number the next unnamed thread gets */
    void set(int next) {
        synchronized (Thread.class) { // JDK 17 numbers threads in a static synchronized method
            try {
                field.setInt(null, next);
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
        }
    }
}
