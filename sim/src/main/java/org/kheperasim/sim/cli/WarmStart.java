package org.kheperasim.sim.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.kheperasim.sim.sandbox.ClassArchive;
import org.kheperasim.sim.sandbox.OwnClasspath;

/**
 * {@code java -jar khepera-sim.jar run …} starts warm: a jar's manifest cannot give the JVM an
 * option, so when the jar has its class-data archive ({@link ClassArchive}) this JVM starts the same
 * command again in a JVM that maps it, passes on its own options, the terminal and the signals, and
 * exits with that JVM's status. A short {@code run} and a small {@code grade} also get the quick compiler only
 * ({@link #QUICK_COMPILER}). Measured on a cold {@code run} of 60 s: 0.78 s of CPU time before,
 * 0.50 s so, of which the first JVM's share is 0.06 s (docs/startup.md). Only for the headless
 * commands where that was measured ({@link #COMMANDS}), only when started with {@code -jar}, and never
 * when the command line already chose an archive ({@code -Xshare}, {@code -XX:SharedArchiveFile}) or
 * the environment gives JVM options.
 */
final class WarmStart {
    /** The commands that start warm. */
    static final List<String> COMMANDS = List.of("run", "evaluate", "grade");
    /** Set in the warm JVM, so that it does not start another. */
    static final String STARTED = "kheperasim.cds.started";

    /**
     * The quick compiler only (C1), as grade's runs have it, for a run of at most {@link #SHORT_RUN}
     * simulated seconds: on a cold {@code run} of 60 s the optimising compiler's work is a third of the
     * CPU time and pays back only for runs of about 1,800 s and more (docs/startup.md has the figures).
     */
    static final String QUICK_COMPILER = "-XX:TieredStopAtLevel=1";
    /** The longest run, in simulated seconds, that gets {@link #QUICK_COMPILER}. */
    static final double SHORT_RUN = 600;
    /**
     * The most runs of a {@code grade} whose grader gets {@link #QUICK_COMPILER}: it replays every run, and on a
     * grading of 60 runs of 600 s the optimising compiler cost it 7.6 s of its 22 s of CPU time, more than the
     * faster replays gave back (0.04 s a run); from about 200 runs on it pays (docs/grading.md).
     */
    static final long SMALL_GRADING = 120;
    /** The environment's JVM options ({@link #optionsFromTheEnvironment}). */
    private static final List<String> ENVIRONMENT_OPTIONS = List.of("JDK_JAVA_OPTIONS", "JAVA_TOOL_OPTIONS",
            "_JAVA_OPTIONS");

    private WarmStart() {
    }

    /**
     * @param args the command's arguments
     * @return true for a {@code run} whose {@code --seconds} is given and at most {@link #SHORT_RUN}
     *     (without it, a run lasts as long as its arena says, 600 s unless it says otherwise)
     */
    static boolean shortRun(String[] args) {
        if (args.length == 0 || !args[0].equals("run")) {
            return false;
        }
        String seconds = null;
        for (int i = 1; i < args.length; i++) {
            if (args[i].equals("--seconds") && i + 1 < args.length) {
                seconds = args[i + 1];
            } else if (args[i].startsWith("--seconds=")) {
                seconds = args[i].substring("--seconds=".length());
            }
        }
        try {
            double s = seconds == null ? Double.NaN : Double.parseDouble(seconds);
            return s > 0 && s <= SHORT_RUN;
        } catch (NumberFormatException e) {
            return false; // the command reports it
        }
    }

    /**
     * @param args the command's arguments
     * @return true for a {@code grade} of at most {@link #SMALL_GRADING} runs: its submissions' folders × its arenas
     *     × its seeds (5 unless given); false when that cannot be told from the arguments
     */
    static boolean smallGrading(String[] args) {
        if (args.length < 2 || !args[0].equals("grade")) {
            return false;
        }
        String submissions = null;
        long arenas = 0;
        String seeds = "5";
        for (int i = 1; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--submissions") && i + 1 < args.length) {
                submissions = args[++i];
            } else if (a.startsWith("--submissions=")) {
                submissions = a.substring("--submissions=".length());
            } else if (a.equals("--seeds") && i + 1 < args.length) {
                seeds = args[++i];
            } else if (a.startsWith("--seeds=")) {
                seeds = a.substring("--seeds=".length());
            } else if (a.startsWith("--arenas=")) {
                arenas++;
            } else if (a.equals("--arenas")) {
                while (i + 1 < args.length && !args[i + 1].startsWith("-")) {
                    arenas++;
                    i++;
                }
            }
        }
        java.io.File[] folders = submissions == null ? null : new java.io.File(submissions).listFiles();
        if (folders == null || arenas == 0) {
            return false;
        }
        long students = 0;
        for (java.io.File f : folders) {
            if (f.isDirectory() && !f.getName().startsWith(".")) {
                students++;
            }
        }
        try {
            long n = Long.parseLong(seeds);
            return n > 0 && students * arenas * n <= SMALL_GRADING;
        } catch (NumberFormatException e) {
            return false; // the command reports it
        }
    }

    /**
     * @return true when the environment gives the JVM options ({@code JDK_JAVA_OPTIONS},
     *     {@code JAVA_TOOL_OPTIONS}, {@code _JAVA_OPTIONS}): each JVM says it picked them up, so a second one
     *     would say it twice, and they might choose an archive of their own
     */
    static boolean optionsFromTheEnvironment() {
        for (String name : ENVIRONMENT_OPTIONS) {
            String v = System.getenv(name);
            if (v != null && !v.isBlank()) {
                return true;
            }
        }
        return false;
    }

    /** @return true when these JVM options choose the compilers themselves */
    private static boolean choosesCompiler(List<String> jvmArgs) {
        for (String a : jvmArgs) {
            if (a.startsWith("-XX:TieredStopAtLevel") || a.endsWith("TieredCompilation") || a.equals("-Xint")
                    || a.equals("-Xcomp")) {
                return true;
            }
        }
        return false;
    }

    /**
     * @param args the command line's arguments
     * @return the warm JVM's exit status, or -1 when this JVM runs the command itself
     */
    static int relaunch(String[] args) {
        if (System.getProperty(STARTED) != null) {
            Orphan.watch();
            return -1;
        }
        if (args.length == 0 || !COMMANDS.contains(args[0]) || optionsFromTheEnvironment()) {
            return -1;
        }
        Optional<Path> archive = ClassArchive.current();
        if (archive.isEmpty()) {
            return -1;
        }
        String[] jvmArgs = ProcessHandle.current().info().arguments().orElse(new String[0]);
        List<String> cmd = command(jvmArgs, archive.get(), args);
        if (cmd.isEmpty()) {
            return -1;
        }
        Process p;
        try {
            p = new ProcessBuilder(cmd).inheritIO().start();
        } catch (IOException e) {
            return -1; // then this JVM runs it, as without an archive
        }
        // Ctrl-C reaches both JVMs (one process group); a SIGTERM sent to this one alone is passed on,
        // and this one ends when that one has finished its trace and its report.
        Runtime.getRuntime().addShutdownHook(new PassOn(p));
        while (true) {
            try {
                return p.waitFor();
            } catch (InterruptedException e) {
                p.destroy();
            }
        }
    }

    /**
     * In the warm JVM: should the JVM the user started die without stopping this one (kill -9, the
     * out-of-memory killer), end as it did, at once, rather than run on unseen. Its parent is gone
     * when this process has another parent (the system adopts an orphan).
     */
    private static final class Orphan extends Thread {
        private final long parent;

        private Orphan(long parent) {
            super("khepera-sim-orphan-watch");
            this.parent = parent;
            setDaemon(true);
        }

        static void watch() {
            Optional<ProcessHandle> p = ProcessHandle.current().parent();
            if (p.isPresent()) {
                new Orphan(p.get().pid()).start();
            }
        }

        @Override
        public void run() {
            while (true) {
                try {
                    Thread.sleep(250);
                } catch (InterruptedException e) {
                    return;
                }
                Optional<ProcessHandle> p = ProcessHandle.current().parent();
                if (p.isEmpty() || p.get().pid() != parent) {
                    Runtime.getRuntime().halt(137); // as the JVM the user started ended: killed (128 + SIGKILL)
                }
            }
        }
    }

    /** Stops the warm JVM as this one was stopped (SIGTERM), and waits for it. No lambda: it costs a start. */
    private static final class PassOn extends Thread {
        private final Process warm;

        PassOn(Process warm) {
            super("khepera-sim-warm-stop");
            this.warm = warm;
        }

        @Override
        public void run() {
            if (warm.isAlive()) {
                warm.destroy();
                try {
                    warm.waitFor();
                } catch (InterruptedException e) {
                    warm.destroyForcibly();
                }
            }
        }
    }

    /**
     * @param jvmArgs this JVM's command line after the program ({@code java}), as the system has it
     * @param archive the archive
     * @param args    the command's arguments
     * @return the warm JVM's command line, or empty when this JVM was not started as
     *     {@code java [options] -jar JAR} or its options already chose an archive
     */
    static List<String> command(String[] jvmArgs, Path archive, String[] args) {
        int jar = -1;
        for (int i = 0; i < jvmArgs.length && jar < 0; i++) {
            String a = jvmArgs[i];
            if (a.equals("-jar")) {
                jar = i;
            } else if (a.startsWith("-Xshare") || a.startsWith("-XX:SharedArchiveFile") || a.startsWith("@")
                    || a.equals("-cp") || a.equals("-classpath") || a.equals("--class-path") || !a.startsWith("-")) {
                return List.of(); // an archive chosen, an argument file, or not started with -jar
            }
        }
        if (jar < 0 || jar + 1 >= jvmArgs.length
                || jvmArgs.length - jar - 2 != args.length || OwnClasspath.entries().isEmpty()) {
            return List.of();
        }
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(List.of(jvmArgs).subList(0, jar));
        cmd.addAll(ClassArchive.jvmOptions(archive));
        if ((shortRun(args) || smallGrading(args)) && !choosesCompiler(List.of(jvmArgs).subList(0, jar))) {
            cmd.add(QUICK_COMPILER);
        }
        cmd.add("-D".concat(STARTED).concat("=true")); // concat: no string-concatenation bootstrap here
        cmd.add("-jar");
        cmd.add(jvmArgs[jar + 1]);
        cmd.addAll(List.of(args));
        return cmd;
    }
}
