package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;

/**
 * Installs this build's artifacts into a local repository, file by file in Maven's layout, as
 * {@code mvn install} does: each module's pom.xml, its jar, and the sources and Javadoc jars beside it.
 * The integration test runs after {@code package}, so the jars are the ones this build just made.
 */
final class LocalRepository {
    /** The modules, in build order; the parent is a pom only. */
    static final List<String> MODULES = List.of("api", "wsu", "controllers", "robot-link", "sim", "testing");
    /** What a student's project depends on by name: installed with its sources and Javadoc, for the IDE. */
    static final List<String> STUDENT_FACING = List.of("api", "testing");

    private LocalRepository() {
    }

    /**
     * @param root the repository's root folder (this build)
     * @param version the project's version
     * @param repository the local repository to install into
     */
    static void install(Path root, String version, Path repository) throws IOException {
        Path group = repository.resolve("org/kheperasim");
        copy(root.resolve("pom.xml"), group.resolve("kheperasim-parent/" + version + "/kheperasim-parent-" + version + ".pom"));
        for (String module : MODULES) {
            Path to = group.resolve(module + "/" + version);
            copy(root.resolve(module + "/pom.xml"), to.resolve(module + "-" + version + ".pom"));
            for (String classifier : List.of("", "-sources", "-javadoc")) {
                Path jar = root.resolve(module + "/target/" + module + "-" + version + classifier + ".jar");
                boolean needed = classifier.isEmpty() || STUDENT_FACING.contains(module);
                assertTrue(Files.isRegularFile(jar) || !needed, jar + " was not built: mvn package makes it for "
                        + module + " (see the source and javadoc plugins in the pom.xml files)");
                if (Files.isRegularFile(jar)) {
                    copy(jar, to.resolve(jar.getFileName()));
                }
            }
        }
    }

    private static void copy(Path from, Path to) throws IOException {
        Files.createDirectories(to.getParent());
        Files.copy(from, to, StandardCopyOption.REPLACE_EXISTING);
    }
}
