package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * What a Java runtime needs to start inside an empty box, found on this machine once: its home
 * folder, the files its links point to outside it (Debian keeps {@code conf/} and {@code cacerts} in
 * {@code /etc}), the shared libraries it and its own libraries load (as {@code ldd} lists them), the
 * C.UTF-8 locale, and the two util-linux tools the box starts it with ({@code setpriv},
 * {@code prlimit}) with their libraries. Nothing else of the host: no shell, no other program.
 *
 * @param javaHome the runtime's home
 * @param files    the host files and folders to show, each at its own path
 * @param setpriv  util-linux's setpriv
 * @param prlimit  util-linux's prlimit
 */
record RuntimeFiles(Path javaHome, List<Path> files, Path setpriv, Path prlimit) {
    private static final Pattern LIBRARY = Pattern.compile("(?:=>\\s*|^\\s+)(/\\S+)\\s+\\(0x");
    private static volatile RuntimeFiles found;

    /** Copies the list. */
    RuntimeFiles {
        files = List.copyOf(files);
    }

    /**
     * @return this machine's runtime files (looked for once)
     * @throws IllegalStateException naming what is missing (setpriv, prlimit)
     */
    static RuntimeFiles find() {
        RuntimeFiles f = found;
        if (f == null) {
            f = look();
            found = f;
        }
        return f;
    }

    private static RuntimeFiles look() {
        Path home = Path.of(System.getProperty("java.home")).toAbsolutePath();
        Path setpriv = onPath("setpriv");
        Path prlimit = onPath("prlimit");
        TreeSet<Path> files = new TreeSet<>();
        files.add(home);
        List<Path> elf = new ArrayList<>(List.of(home.resolve("bin/java"), setpriv, prlimit));
        try (Stream<Path> s = Files.walk(home)) {
            for (Path p : s.toList()) {
                String name = p.getFileName().toString();
                if (Files.isSymbolicLink(p) && !p.toString().contains("/legal/")) {
                    // conf files, cacerts, jvm.cfg on Debian: the link is in the home, its target outside (src.zip's
                    // may be gone)
                    if (Files.exists(p)) {
                        Path target = p.toRealPath();
                        if (!target.startsWith(home) && Files.isRegularFile(target)) {
                            files.add(target);
                        }
                    }
                } else if (name.endsWith(".so") && Files.isRegularFile(p) && p.startsWith(home.resolve("lib"))) {
                    elf.add(p);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list the Java runtime " + home + ": " + e.getMessage(), e);
        }
        files.addAll(libraries(elf));
        files.add(setpriv);
        files.add(prlimit);
        for (String locale : List.of("/usr/lib/locale/C.utf8", "/usr/lib/locale/C.UTF-8")) {
            if (Files.isDirectory(Path.of(locale))) {
                files.add(Path.of(locale));
            }
        }
        return new RuntimeFiles(home, new ArrayList<>(files), setpriv, prlimit);
    }

    /**
     * The shared libraries these programs load, as the dynamic loader finds them ({@code ldd}); the
     * libraries a runtime's graphics and sound libraries load come along, which is harmless: they are
     * only libraries.
     */
    private static List<Path> libraries(List<Path> elf) {
        List<String> cmd = new ArrayList<>(List.of("ldd"));
        elf.forEach(p -> cmd.add(p.toString()));
        TreeSet<Path> out = new TreeSet<>();
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            p.waitFor(30, TimeUnit.SECONDS);
            for (String line : text.split("\n")) {
                Matcher m = LIBRARY.matcher(line);
                if (m.find() && Files.exists(Path.of(m.group(1)))) {
                    out.add(Path.of(m.group(1)));
                }
            }
        } catch (IOException e) {
            throw new IllegalStateException("cannot run ldd to find the Java runtime's libraries ("
                    + e.getMessage() + ")", e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while finding the Java runtime's libraries", e);
        }
        if (out.isEmpty()) {
            throw new IllegalStateException("ldd found no library of " + elf.get(0)
                    + "; the sandbox cannot start Java");
        }
        return new ArrayList<>(out);
    }

    /**
     * @return the program on the PATH (or in /usr/bin, /bin), or in {@link BoxProbe#PATH_PROPERTY}'s folders when it is
     *     set
     */
    static Path onPath(String program) {
        String given = System.getProperty(BoxProbe.PATH_PROPERTY);
        String path = given != null ? given
                : System.getenv().getOrDefault("PATH", "") + ":/usr/bin:/bin:/usr/sbin:/sbin";
        for (String dir : path.split(":")) {
            Path p = dir.isEmpty() ? null : Path.of(dir, program);
            if (p != null && Files.isExecutable(p)) {
                return p.toAbsolutePath();
            }
        }
        throw new IllegalStateException(program + " was not found (util-linux; Debian: apt-get install util-linux)");
    }
}
