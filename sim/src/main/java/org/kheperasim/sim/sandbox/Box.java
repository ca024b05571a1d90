package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * An operating-system box for a JVM that runs code not the user's own: bubblewrap, deny by
 * default. Inside are only the Java runtime ({@link RuntimeFiles}), the files given (the simulator's
 * classpath, one submission's classes, an arena), a private scratch folder {@code /tmp} (a small
 * tmpfs), a fresh {@code /proc} that shows only the box's processes, and a minimal {@code /dev}: no
 * {@code /etc}, no home, no other submission, no shell. No network (a network namespace of its own
 * with nothing in it), its own process, IPC and host-name namespaces, a new session (no way to
 * type into the grader's terminal), and it dies with the process that started it.
 *
 * <p>Inside, {@code setpriv} drops every capability and sets no-new-privileges, and {@code prlimit}
 * sets the {@link BoxLimits}. Those limits must hold even for a grader running as root, which
 * RLIMIT_NPROC does not do for root (root is exempt, and so is a user namespace's uid mapped to
 * root: 10 processes start under {@code ulimit -u 5}). So as root the box runs as a real
 * unprivileged user of its own, a uid that owns nothing on the machine, one per concurrent run (the
 * process count is per uid); as another user, in a user namespace of its own, which on Linux 5.14
 * and later counts its processes apart from the user's others.
 */
public final class Box {
    /** Where the box's command-log channel appears inside it. */
    public static final Path CHANNEL = Path.of("/run/khepera/log.sock");
    /** Where a warm worker's box shows its folder of command-log channels, one socket per run. */
    public static final Path CHANNELS = Path.of("/run/khepera/runs");
    /** The first uid the boxes of a root grader run as (then one block of 256 per grading process). */
    private static final long UID_BASE = 2_000_000L;

    /**
     * What goes in a box.
     *
     * @param readOnly host files and folders shown read-only at their own paths
     * @param writable host files shown writable at their own paths (a trace the run writes)
     * @param channel  a Unix socket shown at {@link #CHANNEL}, or null
     * @param channels a folder of Unix sockets shown read-only at {@link #CHANNELS} (a warm worker's: the
     *                 grader makes a socket there for each run; the box can connect to them, make nothing there
     *                 and see nothing else of the grader's), or null
     * @param network  true to keep the host's network (only {@code serve}, whose clients must reach it)
     * @param limits   the resource limits
     * @param slot     which of the grader's concurrent runs this is, from 0 (picks the uid as root)
     */
    public record Spec(List<Path> readOnly, List<Path> writable, Path channel, Path channels, boolean network,
            BoxLimits limits, int slot) {
        /** Copies the lists. */
        public Spec {
            readOnly = List.copyOf(readOnly);
            writable = List.copyOf(writable);
        }

        /** A box without a folder of channels. */
        public Spec(List<Path> readOnly, List<Path> writable, Path channel, boolean network,
                BoxLimits limits, int slot) {
            this(readOnly, writable, channel, null, network, limits, slot);
        }
    }

    private Box() {
    }

    /**
     * @param spec     what goes in the box
     * @param javaArgs the JVM's options, its main class and arguments (everything after {@code java})
     * @return the command that runs that JVM in the box
     * @throws IllegalStateException if a tool the box needs is missing
     */
    public static List<String> command(Spec spec, List<String> javaArgs) {
        RuntimeFiles rt = RuntimeFiles.find();
        boolean root = isRoot();
        List<String> cmd = new ArrayList<>(List.of(RuntimeFiles.onPath("bwrap").toString(),
                "--unshare-ipc", "--unshare-pid", "--unshare-uts", "--unshare-cgroup-try", "--hostname", "khepera-box",
                "--die-with-parent", "--new-session", "--clearenv", "--setenv", "LANG", "C.UTF-8",
                "--setenv", "HOME", "/tmp",
                "--setenv", "MALLOC_ARENA_MAX", "2", "--chdir", "/tmp"));
        if (!spec.network()) {
            cmd.add("--unshare-net");
        }
        if (root) {
            // Root's bwrap mounts what root can read; setpriv then needs these three to become the box's user.
            cmd.addAll(List.of("--cap-drop", "ALL", "--cap-add", "CAP_SETUID", "--cap-add", "CAP_SETGID", "--cap-add",
                    "CAP_SETPCAP"));
        } else {
            cmd.addAll(List.of("--unshare-user", "--disable-userns"));
        }
        MountPlan plan = new MountPlan();
        plan.first("--proc", "/proc", "--dev", "/dev", "--perms", "1777", "--size",
                Long.toString(spec.limits().scratchBytes()),
                "--tmpfs", "/tmp");
        rt.files().forEach(plan::readOnly);
        spec.readOnly().forEach(plan::readOnly);
        for (Path w : spec.writable()) {
            plan.bind(w, w.toAbsolutePath(), true);
        }
        if (spec.channel() != null) {
            plan.bind(spec.channel(), CHANNEL, true);
        }
        if (spec.channels() != null) {
            // Read-only: connecting to a socket needs no write access to its file system, making a file there would.
            plan.bind(spec.channels(), CHANNELS, false);
        }
        cmd.addAll(plan.args());
        cmd.add("--");
        cmd.add(rt.setpriv().toString());
        if (root) {
            long uid = uid(spec.slot());
            cmd.addAll(List.of("--reuid=" + uid, "--regid=" + uid, "--clear-groups", "--inh-caps=-all",
                    "--bounding-set=-all"));
        } else {
            cmd.add("--inh-caps=-all");
        }
        cmd.addAll(List.of("--no-new-privs", "--", rt.prlimit().toString()));
        cmd.addAll(spec.limits().prlimitArgs());
        cmd.add("--");
        cmd.add(rt.javaHome().resolve("bin/java").toString());
        cmd.addAll(BoxLimits.javaOptions());
        cmd.addAll(List.of("-Djava.io.tmpdir=/tmp", "-Duser.home=/tmp"));
        cmd.addAll(javaArgs);
        return cmd;
    }

    /**
     * @param slot the run's slot among the grader's concurrent runs
     * @return the uid a root grader's box runs as: its own per grading process and slot, owning nothing
     */
    public static long uid(int slot) {
        return UID_BASE + (ProcessHandle.current().pid() % 4_000_000L) * 256 + Math.floorMod(slot, 256);
    }

    /** @return true when this process runs as root (the box then changes to a user of its own) */
    public static boolean isRoot() {
        try {
            return ((Number) Files.getAttribute(Path.of("/proc/self"), "unix:uid")).intValue() == 0;
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return false;
        }
    }

    /**
     * Let the box's user (as root: {@link #uid}) write a file the box is given writable.
     *
     * @param file a file made by the grader
     * @param slot the run's slot
     * @throws IOException if its owner cannot be changed
     */
    public static void handOver(Path file, int slot) throws IOException {
        if (isRoot()) {
            Files.setAttribute(file, "unix:uid", (int) uid(slot));
            Files.setAttribute(file, "unix:gid", (int) uid(slot));
        }
    }
}
