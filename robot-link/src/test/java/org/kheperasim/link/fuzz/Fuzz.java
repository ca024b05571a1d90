package org.kheperasim.link.fuzz;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * A small property-testing harness for the readers: generate inputs from a seeded random source,
 * check a property on each, report what failed with the input and the seed that makes it again.
 *
 * <p>In the normal build each property runs a modest number of inputs from a fixed seed, so the
 * suite is fast and repeatable. With {@code -Dfuzz.tries=N} (the {@code fuzz} Maven profile sets a
 * million) each runs N inputs from a fresh seed, keeps going after a failure to count them, and
 * prints its figures (inputs, seconds, inputs per second, failures, the slowest input) to standard
 * output and to {@code target/fuzz-figures.txt}. {@code -Dfuzz.seed=S} repeats a run.
 *
 * <p>Failures are grouped by exception type and message shape, so one bug met a thousand times
 * counts once among the distinct failures shown; each shown failure is first made smaller with the
 * property's own shrinker, if it has one.
 */
public final class Fuzz {

    private static final int MAX_SHOWN = 8;
    private static final int MAX_SHOWN_CHARS = 1500;

    /**
     * @param <T> the input type
     * @param name what is checked, for the report
     * @param normalTries how many inputs in the normal build
     * @param generator makes one input from a random source
     * @param property throws (an assertion error or any exception) when the input breaks the property
     * @param shrinker smaller variants of a failing input to try, or null
     * @param show how an input is printed
     * @throws AssertionError listing the distinct failures
     */
    public static <T> void check(String name, int normalTries, Function<SplittableRandom, T> generator, Consumer<T> property,
            Function<T, List<T>> shrinker, Function<T, String> show) {
        int fuzzTries = Integer.getInteger("fuzz.tries", 0);
        boolean fuzzing = fuzzTries > 0;
        int tries = fuzzing ? fuzzTries : normalTries;
        long seed = Long.getLong("fuzz.seed", fuzzing ? System.nanoTime() : name.hashCode() * 0x9E3779B97F4A7C15L);
        Map<String, Failure> failures = new LinkedHashMap<>();
        int failed = 0;
        long slowestNanos = 0;
        long start = System.nanoTime();
        for (int i = 0; i < tries; i++) {
            long inputSeed = seed + i * 0x9E3779B97F4A7C15L;
            T input = generator.apply(new SplittableRandom(inputSeed));
            long t0 = System.nanoTime();
            Throwable broke = test(property, input);
            slowestNanos = Math.max(slowestNanos, System.nanoTime() - t0);
            if (broke != null) {
                failed++;
                String key = signature(broke);
                if (!failures.containsKey(key) && failures.size() < MAX_SHOWN) {
                    T small = shrink(input, broke, property, shrinker);
                    failures.put(key, new Failure(i, inputSeed, show.apply(small), test(property, small)));
                }
                if (!fuzzing) {
                    break;
                }
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        String figures = String.format(Locale.ROOT, "fuzz %s: %,d inputs in %.1f s (%,.0f inputs/s), %d failing (%d distinct),"
                + " slowest input %.1f ms, seed %d", name, tries, seconds, tries / Math.max(seconds, 1e-9), failed,
                failures.size(), slowestNanos / 1e6, seed);
        System.out.println(figures);
        if (fuzzing) {
            record(figures);
        }
        if (!failures.isEmpty()) {
            StringBuilder b = new StringBuilder(figures).append('\n');
            for (Failure f : failures.values()) {
                b.append("\n-- input #").append(f.index).append(" (repeat with -Dfuzz.seed=").append(f.seed)
                        .append(" -Dfuzz.tries=1), made smaller:\n").append(clip(f.shown)).append("\n-> ").append(f.error);
            }
            throw new AssertionError(b.toString(), failures.values().iterator().next().error);
        }
    }

    /** {@link #check} for text inputs, shrunk by dropping lines, then characters. */
    public static void checkText(String name, int normalTries, Function<SplittableRandom, String> generator,
            Consumer<String> property) {
        check(name, normalTries, generator, property, Fuzz::smallerTexts, Fuzz::visible);
    }

    /** @return the number of inputs a property runs with now (its own number, or the fuzz run's) */
    public static int tries(int normalTries) {
        int fuzzTries = Integer.getInteger("fuzz.tries", 0);
        return fuzzTries > 0 ? fuzzTries : normalTries;
    }

    private static Throwable test(Consumer<?> property, Object input) {
        try {
            @SuppressWarnings("unchecked")
            Consumer<Object> p = (Consumer<Object>) property;
            p.accept(input);
            return null;
        } catch (Throwable t) {
            if (t instanceof VirtualMachineError && !(t instanceof StackOverflowError || t instanceof OutOfMemoryError)) {
                throw (VirtualMachineError) t;
            }
            return t;
        }
    }

    /** The exception's type and its message with the numbers and quoted parts blanked out. */
    private static String signature(Throwable t) {
        String m = String.valueOf(t.getMessage());
        m = m.replaceAll("'[^']*'", "'_'").replaceAll("\\d+", "#");
        return t.getClass().getName() + ": " + (m.length() > 80 ? m.substring(0, 80) : m);
    }

    private static <T> T shrink(T input, Throwable broke, Consumer<T> property, Function<T, List<T>> shrinker) {
        if (shrinker == null) {
            return input;
        }
        String key = signature(broke);
        T best = input;
        for (int steps = 0; steps < 2000; steps++) {
            T next = null;
            for (T candidate : shrinker.apply(best)) {
                Throwable t = test(property, candidate);
                if (t != null && signature(t).equals(key)) {
                    next = candidate;
                    break;
                }
            }
            if (next == null) {
                return best;
            }
            best = next;
        }
        return best;
    }

    /** Smaller texts: without halves, quarters... down to single lines (from the end), then without one character. */
    static List<String> smallerTexts(String text) {
        List<String> out = new ArrayList<>();
        List<String> lines = List.of(text.split("\n", -1));
        int n = lines.size();
        for (int parts = 2; n > 1 && out.size() < 400; parts *= 2) {
            int size = Math.max(1, (n + parts - 1) / parts);
            for (int from = (n - 1) / size * size; from >= 0 && out.size() < 400; from -= size) {
                List<String> rest = new ArrayList<>(lines.subList(0, from));
                rest.addAll(lines.subList(Math.min(n, from + size), n));
                out.add(String.join("\n", rest));
            }
            if (size == 1) {
                break;
            }
        }
        if (text.length() <= 200) {
            for (int i = text.length() - 1; i >= 0; i--) {
                out.add(text.substring(0, i) + text.substring(i + 1));
            }
        }
        return out;
    }

    /** The text with control characters and non-ASCII shown as escapes, so a report shows what was read. */
    public static String visible(String text) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n') {
                b.append("\\n\n");
            } else if (c < 0x20 || c > 0x7E) {
                b.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    private static String clip(String s) {
        return s.length() <= MAX_SHOWN_CHARS ? s : s.substring(0, MAX_SHOWN_CHARS) + "... (" + s.length() + " characters)";
    }

    private static void record(String figures) {
        try {
            Path out = Path.of("target", "fuzz-figures.txt");
            Files.createDirectories(out.getParent());
            Files.writeString(out, figures + "\n", StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        } catch (IOException e) {
            System.out.println("(cannot record the figures in target/fuzz-figures.txt: " + e + ")");
        }
    }

    private record Failure(int index, long seed, String shown, Throwable error) {
    }

    private Fuzz() {
    }
}
