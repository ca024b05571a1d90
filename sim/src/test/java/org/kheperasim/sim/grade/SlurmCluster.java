package org.kheperasim.sim.grade;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * A private single-node Slurm cluster for a test: its own munged (own socket, a copy of the
 * system's key), slurmctld and slurmd in the foreground on free ports, with a configuration in a
 * temporary folder (no cgroups: proctrack/linuxproc, task/none; no accounting). Needs root and
 * Debian's slurm-wlm (which brings munge). {@link #close()} stops the daemons it started.
 */
final class SlurmCluster implements AutoCloseable {
    static final List<String> TOOLS = List.of("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo");

    private final Path dir;
    private final List<Process> daemons = new ArrayList<>();

    private SlurmCluster(Path dir) {
        this.dir = dir;
    }

    /** @return why a cluster cannot start here, or empty when it can */
    static Optional<String> missing() {
        for (String t : TOOLS) {
            if (which(t) == null) {
                return Optional.of(t + " is not installed (apt-get install -y slurm-wlm)");
            }
        }
        if (!Files.isReadable(Path.of("/etc/munge/munge.key"))) {
            return Optional.of("/etc/munge/munge.key is not readable (run as root; slurm-wlm's munge makes the key)");
        }
        return Optional.empty();
    }

    static SlurmCluster start(Path dir) throws IOException, InterruptedException {
        SlurmCluster c = new SlurmCluster(dir);
        try {
            c.boot();
        } catch (IOException | InterruptedException | RuntimeException e) {
            c.close();
            throw e;
        }
        return c;
    }

    private void boot() throws IOException, InterruptedException {
        Files.createDirectories(dir.resolve("state"));
        Files.createDirectories(dir.resolve("spool"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
        Path key = dir.resolve("munge.key");
        Files.copy(Path.of("/etc/munge/munge.key"), key);
        Files.setPosixFilePermissions(key, PosixFilePermissions.fromString("rw-------"));
        String host = output(List.of("hostname", "-s")).strip();
        int cpus = Runtime.getRuntime().availableProcessors();
        String conf = String.join("\n",
                "ClusterName=gradetest",
                "SlurmctldHost=" + host + "(127.0.0.1)",
                "SlurmUser=root", "SlurmdUser=root",
                "AuthType=auth/munge", "CredType=cred/munge", "AuthInfo=socket=" + dir.resolve("munge.sock"),
                "StateSaveLocation=" + dir.resolve("state"), "SlurmdSpoolDir=" + dir.resolve("spool"),
                "SlurmctldPidFile=" + dir.resolve("slurmctld.pid"), "SlurmdPidFile=" + dir.resolve("slurmd.pid"),
                "SlurmctldLogFile=" + dir.resolve("slurmctld.log"), "SlurmdLogFile=" + dir.resolve("slurmd.log"),
                "SlurmctldPort=" + freePort(), "SlurmdPort=" + freePort(),
                "ProctrackType=proctrack/linuxproc", "TaskPlugin=task/none",
                "JobAcctGatherType=jobacct_gather/none", "AccountingStorageType=accounting_storage/none",
                "SelectType=select/cons_tres", "SelectTypeParameters=CR_Core_Memory", "MpiDefault=none",
                "ReturnToService=2", "SchedulerParameters=sched_interval=2",
                "NodeName=gradenode NodeHostname=" + host + " NodeAddr=127.0.0.1 CPUs=" + cpus + " RealMemory=2000 State=UNKNOWN",
                "PartitionName=grade Nodes=gradenode Default=YES MaxTime=INFINITE State=UP", "");
        Files.writeString(dir.resolve("slurm.conf"), conf);
        daemon("munged", which("munged"), "-F", "--force", "--socket=" + dir.resolve("munge.sock"),
                "--pid-file=" + dir.resolve("munged.pid"), "--log-file=" + dir.resolve("munged.log"),
                "--seed-file=" + dir.resolve("munged.seed"), "--key-file=" + key);
        waitFor(() -> Files.exists(dir.resolve("munge.sock")), "munged's socket", "munged");
        daemon("slurmctld", which("slurmctld"), "-D", "-i");
        Thread.sleep(1000);
        daemon("slurmd", which("slurmd"), "-D", "-N", "gradenode");
        waitFor(() -> output(List.of(which("sinfo"), "-h", "-o", "%T")).strip().equals("idle"), "the node to be idle", "slurmd");
    }

    /** @return the environment a Slurm client (sbatch, squeue) needs to reach this cluster */
    Map<String, String> env() {
        return Map.of("SLURM_CONF", dir.resolve("slurm.conf").toString());
    }

    /** Runs a Slurm client; @return its standard output @throws IllegalStateException if it fails */
    String run(List<String> command) {
        List<String> full = new ArrayList<>(command);
        full.set(0, which(full.get(0)));
        return output(full);
    }

    /** Waits until none of the jobs is queued or running. */
    void await(String jobs, long seconds) throws InterruptedException {
        waitFor(() -> run(List.of("squeue", "-h", "-j", jobs)).isBlank(), "jobs " + jobs + " to end", "slurmctld", seconds);
    }

    private String output(List<String> command) {
        try {
            ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
            pb.environment().putAll(env());
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException(String.join(" ", command) + " failed: " + out);
            }
            return out;
        } catch (IOException e) {
            throw new IllegalStateException(String.join(" ", command) + " failed: " + e, e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }

    private void daemon(String name, String... command) throws IOException {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(dir.resolve(name + ".out").toFile());
        pb.environment().putAll(env());
        daemons.add(pb.start());
    }

    private interface Check {
        boolean ok() throws Exception;
    }

    private void waitFor(Check check, String what, String log) throws InterruptedException {
        waitFor(check, what, log, 30);
    }

    private void waitFor(Check check, String what, String log, long seconds) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        Exception last = null;
        while (System.nanoTime() < end) {
            try {
                if (check.ok()) {
                    return;
                }
            } catch (Exception e) {
                last = e;
            }
            Thread.sleep(500);
        }
        String out;
        try {
            out = Files.readString(dir.resolve(log + ".out"));
        } catch (IOException e) {
            out = "(no output)";
        }
        throw new IllegalStateException("timed out waiting for " + what + " (" + last + "); " + log + " said:\n" + out);
    }

    @Override
    public void close() {
        for (int i = daemons.size() - 1; i >= 0; i--) {
            Process p = daemons.get(i);
            p.destroy();
            try {
                if (!p.waitFor(10, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    static String which(String tool) {
        for (String d : (System.getenv().getOrDefault("PATH", "") + ":/usr/sbin:/sbin:/usr/local/sbin").split(":")) {
            Path p = Path.of(d.isEmpty() ? "." : d, tool);
            if (Files.isExecutable(p)) {
                return p.toString();
            }
        }
        return null;
    }
}
