package org.kheperasim.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * A Maven build of another project, in a process of its own, offline, with a local repository of its own:
 * what a student's {@code mvn test} does on their machine after installing the simulator. Whatever that
 * repository lacks (plugins, JUnit) is copied from the outer build's local repository, which it reads as
 * its only remote repository (a {@code file:} URL, which offline mode is told to allow); nothing is
 * fetched from the network and nothing is written outside the temporary folder.
 */
final class NestedMaven {
    private final Path mvn;
    private final Path settings;
    private final Path repository;

    /** What a build printed and how it ended. */
    record Result(int exit, String log, double seconds) {
    }

    /**
     * @param dir a temporary folder: the settings file and the local repository go there
     * @param outerRepository the outer build's local repository, read as the only remote one
     */
    NestedMaven(Path dir, Path outerRepository) throws IOException {
        String home = System.getProperty("kheperasim.mavenHome", "");
        this.mvn = home.isEmpty() ? Path.of("mvn") : Path.of(home, "bin", "mvn");
        this.repository = Files.createDirectories(dir.resolve("repository"));
        String url = outerRepository.toUri().toString();
        String repo = "<id>central</id><url>" + url + "</url><releases><checksumPolicy>ignore</checksumPolicy></releases>"
                + "<snapshots><enabled>false</enabled></snapshots>";
        this.settings = dir.resolve("settings.xml");
        Files.writeString(settings, "<settings>\n  <profiles><profile><id>outer</id>\n"
                + "    <repositories><repository>" + repo + "</repository></repositories>\n"
                + "    <pluginRepositories><pluginRepository>" + repo + "</pluginRepository></pluginRepositories>\n"
                + "  </profile></profiles>\n  <activeProfiles><activeProfile>outer</activeProfile></activeProfiles>\n</settings>\n");
    }

    /** @return the local repository the builds use */
    Path repository() {
        return repository;
    }

    /** @return the Maven command line, options included, that builds offline against {@link #repository()} */
    List<String> mvn() {
        return List.of(mvn.toString(), "-o", "-ntp", "-s", settings.toString(), "-Dmaven.repo.local=" + repository,
                "-Daether.offline.protocols=file", "-Dstyle.color=never");
    }

    /**
     * @param project the project's folder
     * @param goals what to run, e.g. {@code test}
     * @return how it ended, with its log
     */
    Result run(Path project, String... goals) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(mvn());
        cmd.add("-B");
        cmd.addAll(List.of(goals));
        return exec(project, cmd, Map.of());
    }

    /**
     * @param dir the working folder
     * @param cmd a command that runs Maven (a script given this Maven in {@code env})
     * @param env variables to set for it
     * @return how it ended, with its log
     */
    Result exec(Path dir, List<String> cmd, Map<String, String> env) throws IOException, InterruptedException {
        Path log = Files.createTempFile(dir.getParent(), "mvn-", ".log");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        // The student's build sees none of the outer build's JVM options; Maven's own JVM is short-lived, so it
        // starts faster without the optimising compiler.
        pb.environment().put("MAVEN_OPTS", "-XX:TieredStopAtLevel=1");
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().putAll(env);
        long start = System.nanoTime();
        Process p = pb.start();
        if (!p.waitFor(480, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            throw new AssertionError(String.join(" ", cmd) + " in " + dir + " did not end in 480 s:\n" + Files.readString(log));
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        String text = Files.readString(log);
        Files.delete(log);
        return new Result(p.exitValue(), text, seconds);
    }
}
