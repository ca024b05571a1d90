package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Whether this machine can make a {@link Box}: Linux, bubblewrap and util-linux installed, and (for
 * a user other than root) unprivileged user namespaces allowed. Found out once, by starting
 * {@code java -version} in a real box, and told as one line that says what is missing and how to
 * get it.
 */
public final class BoxProbe {
    /**
     * The folders the sandbox's programs (bwrap, setpriv, prlimit) are looked for in, instead of the PATH and
     * /usr/bin, /bin, /usr/sbin, /sbin: for bubblewrap installed elsewhere, and for trying a machine without
     * it ({@code -Dkheperasim.sandbox.path=/nonexistent}).
     */
    public static final String PATH_PROPERTY = "kheperasim.sandbox.path";

    private static volatile Optional<String> cached;

    private BoxProbe() {
    }

    /** @return why no box can be made here, or empty when it can */
    public static Optional<String> unavailable() {
        Optional<String> c = cached;
        if (c == null) {
            c = Optional.ofNullable(probe());
            cached = c;
        }
        return c;
    }

    /**
     * @param command what needs the box, e.g. {@code grade}
     * @param reason  why there is none ({@link #unavailable()})
     * @return the one-line error: what is missing, how to get it, and how to go on without the box
     */
    public static String refusal(String command, String reason) {
        return command + " runs code that is not your own in a bubblewrap sandbox, but " + reason
                + "; or give --no-sandbox to " + command + " without it (only for code you trust: it can then read and"
                + " write what you can, and reach the network). See docs/grading.md, \"The sandbox\".";
    }

    private static String probe() {
        String os = System.getProperty("os.name", "?");
        if (!os.toLowerCase(Locale.ROOT).startsWith("linux")) {
            return "the sandbox needs Linux (bubblewrap and its namespaces), and this is " + os;
        }
        try {
            RuntimeFiles.onPath("bwrap");
        } catch (IllegalStateException e) {
            return "bubblewrap (bwrap) is not installed: install it (Debian, Ubuntu: apt-get install bubblewrap;"
                    + " Fedora: dnf install bubblewrap)";
        }
        List<String> cmd;
        try {
            cmd = Box.command(new Box.Spec(List.of(), List.of(), null, false, BoxLimits.forCommand(1), 0),
                    List.of("-version"));
        } catch (IllegalStateException e) {
            return e.getMessage();
        }
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(60, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return "a test of the sandbox (java -version in it) did not end within 60 s";
            }
            if (p.exitValue() == 0) {
                return null;
            }
            return explain(out.strip());
        } catch (IOException e) {
            return "bubblewrap could not be started (" + e.getMessage() + ")";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "the test of the sandbox was interrupted";
        }
    }

    /** Turns what a failed box said into what to do. */
    static String explain(String output) {
        String first = output.lines().findFirst().orElse("(no message)");
        String o = output.toLowerCase(Locale.ROOT);
        if (o.contains("namespace") || o.contains("uid map") || o.contains("operation not permitted")
                || o.contains("permission denied")) {
            return "bubblewrap could not make its namespaces (\"" + first
                    + "\"): unprivileged user namespaces are switched"
                    + " off. Allow them (Ubuntu 23.10 and later: sysctl -w"
                    + " kernel.apparmor_restrict_unprivileged_userns=0, or an AppArmor profile for bwrap; Debian 11 and"
                    + " older: sysctl -w kernel.unprivileged_userns_clone=1; RHEL 7: sysctl -w"
                    + " user.max_user_namespaces=15000), or run grade as root";
        }
        List<String> lines = new ArrayList<>(output.lines().limit(3).toList());
        return "java -version failed in the sandbox: " + String.join(" | ", lines);
    }
}
