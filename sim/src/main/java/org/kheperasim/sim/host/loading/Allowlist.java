package org.kheperasim.sim.host.loading;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiPredicate;
import org.kheperasim.sim.host.loading.AllowlistEntry.Kind;

/**
 * The controller allowlist: what untrusted controller code may name of the Java platform and the
 * simulator, read from {@code controller-allowlist.txt} beside this class (its format and every
 * entry's reason are in the file, and {@code docs/controller-rules.md} shows it). It answers about
 * names only; {@link ControllerPolicy} looks a member up where the JVM finds it before asking.
 */
final class Allowlist {
    /** The file, as a resource beside this class. */
    static final String RESOURCE = "controller-allowlist.txt";

    private static final Allowlist BUNDLED = load();

    private final List<AllowlistEntry> entries;
    /**
     * Answers already given, by class, member and parameters: a run of many robots checks the same
     * controller once per robot. They are asked of platform and simulator classes only, whose place
     * in the hierarchy (what the {@code isSubclass} of the queries answers) is the same for every
     * loader.
     */
    private final Map<String, Boolean> answers = new ConcurrentHashMap<>();

    /** @param entries the list's entries, in the file's order */
    Allowlist(List<AllowlistEntry> entries) {
        this.entries = List.copyOf(entries);
    }

    /** @return the list the simulator ships */
    static Allowlist bundled() {
        return BUNDLED;
    }

    private static Allowlist load() {
        try (InputStream in = Allowlist.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("the controller allowlist " + RESOURCE + " is missing from the build");
            }
            return new Allowlist(
                    AllowlistParser.parse(RESOURCE, new String(in.readAllBytes(), StandardCharsets.UTF_8)));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the controller allowlist " + RESOURCE, e);
        }
    }

    /** @return every entry, in the file's order */
    List<AllowlistEntry> entries() {
        return entries;
    }

    /**
     * @param binaryName a class ({@code java.lang.Thread$State})
     * @param isSubclass answers whether a class (binary name) is a subclass of another, for the
     *     entries limited to subclasses
     * @return whether controller code may name the type (a cast, a superclass, a class constant)
     */
    boolean allowsType(String binaryName, BiPredicate<String, String> isSubclass) {
        return answers.computeIfAbsent(binaryName, n -> !naming(n, false, isSubclass).isEmpty());
    }

    /**
     * @param binaryName the class that declares the member
     * @param member its name ({@code <init>} for a constructor)
     * @param parameters its parameter types as binary names, or null for a field
     * @param asBootstrap true when it is named as the bootstrap method of an invokedynamic or a
     *     dynamic constant: then only the bootstrap entries count, otherwise only the others
     * @param isSubclass see {@link #allowsType}
     * @return whether controller code may use it
     */
    boolean allowsMember(String binaryName, String member, List<String> parameters, boolean asBootstrap,
            BiPredicate<String, String> isSubclass) {
        String key = binaryName + (asBootstrap ? "#" : ".") + member
                + (parameters == null ? "" : parameters.toString());
        return answers.computeIfAbsent(key, k -> decide(binaryName, member, parameters, asBootstrap, isSubclass));
    }

    private boolean decide(String binaryName, String member, List<String> parameters, boolean asBootstrap,
            BiPredicate<String, String> isSubclass) {
        for (AllowlistEntry e : naming(binaryName, asBootstrap, isSubclass)) {
            if (e.allows(member, parameters)) {
                return true;
            }
        }
        return false;
    }

    /**
     * @param member the member's name, or null for the type
     * @param parameters its parameter types, or null
     * @return what the refused group says of such a use (its most specific entry), or null
     */
    String refusalReason(String binaryName, String member, List<String> parameters,
            BiPredicate<String, String> isSubclass) {
        AllowlistEntry best = null;
        for (AllowlistEntry e : entries) {
            if (e.group().kind() == Kind.REFUSED && names(e, binaryName, isSubclass) && e.mentions(member, parameters)
                    && (best == null || e.classes().rank() > best.classes().rank())) {
                best = e;
            }
        }
        return best == null ? null : best.reason();
    }

    /** The allowing entries of the highest rank that name the class (several only when ranks tie). */
    private List<AllowlistEntry> naming(String binaryName, boolean bootstrap, BiPredicate<String, String> isSubclass) {
        List<AllowlistEntry> best = new ArrayList<>();
        int rank = -1;
        Kind wanted = bootstrap ? Kind.BOOTSTRAP : Kind.ALLOWED;
        for (AllowlistEntry e : entries) {
            if (e.group().kind() != wanted || !names(e, binaryName, isSubclass)) {
                continue;
            }
            int r = e.classes().rank();
            if (r > rank) {
                best.clear();
                rank = r;
            }
            if (r == rank) {
                best.add(e);
            }
        }
        return best;
    }

    private static boolean names(AllowlistEntry e, String binaryName, BiPredicate<String, String> isSubclass) {
        if (!e.classes().names(binaryName)) {
            return false;
        }
        String mustExtend = e.classes().mustExtend();
        return mustExtend == null || isSubclass.test(binaryName, mustExtend);
    }
}
