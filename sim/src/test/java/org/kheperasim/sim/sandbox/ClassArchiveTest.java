package org.kheperasim.sim.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An archive is handed to a JVM only when it fits the jar as it is now and this JVM build: a JVM
 * given one that does not fit runs with no archive at all, the JDK's own either (slower than none).
 */
class ClassArchiveTest {
    @TempDir
    Path dir;

    @Test
    void anArchiveFitsOnlyTheJarItWasMadeForAsItIsNow() throws IOException {
        Path jar = Files.write(dir.resolve("khepera-sim.jar"), new byte[] {1, 2, 3});
        Path archive = ClassArchive.beside(jar);
        assertEquals(dir.resolve("khepera-sim.jsa"), archive);
        assertFalse(ClassArchive.fits(archive, jar), "no archive");
        Files.write(archive, header(System.getProperty("java.vm.version")));
        assertFalse(ClassArchive.fits(archive, jar), "no key beside it");
        Files.writeString(ClassArchive.key(archive), ClassArchive.madeFor(jar), StandardCharsets.UTF_8);
        assertTrue(ClassArchive.fits(archive, jar));

        Path other = Files.write(dir.resolve("other.jar"), new byte[] {1, 2, 3});
        Files.setLastModifiedTime(other, Files.getLastModifiedTime(jar));
        assertFalse(ClassArchive.fits(archive, other), "a copy of the jar elsewhere: the JVM would refuse it");
        Files.setLastModifiedTime(jar, FileTime.fromMillis(Files.getLastModifiedTime(jar).toMillis() + 2000));
        assertFalse(ClassArchive.fits(archive, jar), "the jar was rebuilt");
    }

    @Test
    void anArchiveOfAnotherJvmBuildOrNoArchiveAtAllDoesNotFit() throws IOException {
        Path jar = Files.write(dir.resolve("khepera-sim.jar"), new byte[] {1, 2, 3});
        Path archive = ClassArchive.beside(jar);
        Files.writeString(ClassArchive.key(archive), ClassArchive.madeFor(jar), StandardCharsets.UTF_8);
        Files.write(archive, header("11.0.2+9"));
        assertFalse(ClassArchive.fits(archive, jar), "another JVM build's");
        Files.writeString(archive, "not an archive");
        assertFalse(ClassArchive.fits(archive, jar), "not an archive");
        byte[] dynamic = header(System.getProperty("java.vm.version"));
        dynamic[0] = (byte) 0xa8; // a dynamic archive's magic: it needs its base archive too
        Files.write(archive, dynamic);
        assertFalse(ClassArchive.fits(archive, jar), "a dynamic archive");
    }

    @Test
    void theOptionsNameTheArchiveAndSilenceTheJvmAboutIt() {
        Path archive = dir.resolve("khepera-sim.jsa");
        List<String> options = ClassArchive.jvmOptions(archive);
        assertEquals("-XX:SharedArchiveFile=" + archive, options.get(0));
        assertTrue(options.contains("-Xshare:auto"), options.toString());
        assertTrue(options.contains("-Xlog:cds=off"), options.toString());
    }

    @Test
    void testClassesFromFoldersHaveNoArchive() {
        assertTrue(ClassArchive.current().isEmpty(), "the tests run from target/classes: " + ClassArchive.current());
        assertEquals(List.of(), ClassArchive.jvmOptions());
    }

    /** The first bytes of a static archive made by the JVM build {@code version}, as HotSpot 17 lays them. */
    private static byte[] header(String version) {
        byte[] b = new byte[8192];
        b[0] = (byte) 0xa2;
        b[1] = (byte) 0xab;
        b[2] = 0x0b;
        b[3] = (byte) 0xf0;
        byte[] ident = ("OpenJDK 64-Bit Server VM (" + version + ") for linux-amd64")
                .getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(ident, 0, b, 617, ident.length);
        return b;
    }
}
