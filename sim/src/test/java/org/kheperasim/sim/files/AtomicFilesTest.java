package org.kheperasim.sim.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.run.SettingsFile;

/** Issue 14: every save keeps the file's mode and symbolic links, and leaves nothing behind. */
class AtomicFilesTest {

    private static boolean posix() {
        return FileSystems.getDefault().supportedFileAttributeViews().contains("posix");
    }

    private static List<Path> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted().toList();
        }
    }

    @Test
    void replacesTheContentAndKeepsTheFilesMode(@TempDir Path dir) throws IOException {
        assumeTrue(posix(), "this file system has no POSIX permissions (not Linux or macOS)");
        Path file = dir.resolve("lab.arena");
        Files.writeString(file, "old");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r-----"));
        ArenaFormat.save(ArenaFormat.loadBundled("lab"), file);
        assertEquals(ArenaFormat.write(ArenaFormat.loadBundled("lab")), Files.readString(file));
        assertEquals("rw-r-----", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));

        Path settings = dir.resolve("lab.settings");
        Files.writeString(settings, "");
        Files.setPosixFilePermissions(settings, PosixFilePermissions.fromString("rw-rw-r--"));
        SettingsFile.save(Settings.defaults().with("noise.reading", "0"), settings);
        assertEquals("rw-rw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(settings)));

        Path edits = dir.resolve("run.edits");
        Files.writeString(edits, "");
        Files.setPosixFilePermissions(edits, PosixFilePermissions.fromString("rwxr-xr-x"));
        new EditLog().save(edits);
        assertEquals("rwxr-xr-x", PosixFilePermissions.toString(Files.getPosixFilePermissions(edits)));
        assertEquals(List.of(file, settings, edits).stream().sorted().toList(), list(dir));
    }

    @Test
    void aNewFileGetsTheUsualPermissionsNotPrivateOnes(@TempDir Path dir) throws IOException {
        assumeTrue(posix(), "this file system has no POSIX permissions (not Linux or macOS)");
        Path plain = dir.resolve("plain");
        Files.writeString(plain, "x");
        Path saved = dir.resolve("saved");
        AtomicFiles.write(saved, "x");
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(saved),
                "a new file gets what any new file gets (the umask), not the 0600 of a temporary file");
    }

    @Test
    void writesThroughASymbolicLinkWhichStaysALink(@TempDir Path dir) throws IOException {
        Path real = Files.createDirectories(dir.resolve("versioned")).resolve("maze.arena");
        Files.writeString(real, "old");
        Path link = dir.resolve("maze.arena");
        Files.createSymbolicLink(link, Path.of("versioned", "maze.arena"));
        Path chain = dir.resolve("current.arena");
        Files.createSymbolicLink(chain, link.getFileName());

        ArenaFormat.save(ArenaFormat.loadBundled("maze"), chain);
        assertTrue(Files.isSymbolicLink(link) && Files.isSymbolicLink(chain), "the links are still links");
        assertEquals(ArenaFormat.write(ArenaFormat.loadBundled("maze")), Files.readString(real));
        assertEquals(List.of(real), list(real.getParent()), "the temporary file was made beside the real file");
    }

    @Test
    void aFailedSaveLeavesTheOldFileAndNoTemporaryFile(@TempDir Path dir) throws IOException {
        Path target = dir.resolve("busy");
        Files.createDirectories(target.resolve("inside"));
        IOException e = assertThrows(IOException.class, () -> AtomicFiles.write(target, "new"));
        assertTrue(e.toString().contains("busy"), e.toString());
        assertEquals(List.of(target), list(dir), "no temporary file is left after the rename failed");
        assertTrue(Files.isDirectory(target.resolve("inside")));

        Path missing = dir.resolve("no-such-folder").resolve("x.arena");
        assertThrows(IOException.class, () -> AtomicFiles.write(missing, "x"));
        assertEquals(List.of(target), list(dir));
    }

    @Test
    void leftoversOfAKilledSaveAreRemovedByTheNextSave(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("run.settings");
        long deadPid = findDeadPid();
        Path stale = dir.resolve(AtomicFiles.temporaryName("run.settings", deadPid, 1));
        Files.writeString(stale, "half a fi");
        Path alive = dir.resolve(AtomicFiles.temporaryName("run.settings", ProcessHandle.current().parent()
                .map(ProcessHandle::pid).orElse(1L), 7));
        Files.writeString(alive, "another process is saving");
        Path other = dir.resolve(AtomicFiles.temporaryName("other.settings", deadPid, 1));
        Files.writeString(other, "not ours");

        AtomicFiles.write(file, "noise.reading=0\n");
        assertEquals("noise.reading=0\n", Files.readString(file));
        assertEquals(List.of(alive, other, file).stream().sorted().toList(), list(dir),
                "only the dead process's leftover of this very file is gone");
    }

    @Test
    void followsARelativeLinkInAnotherFolderAndRefusesALoop(@TempDir Path dir) throws IOException {
        Path a = dir.resolve("a");
        Path b = dir.resolve("b");
        Files.createSymbolicLink(a, b.getFileName());
        Files.createSymbolicLink(b, a.getFileName());
        assertThrows(IOException.class, () -> AtomicFiles.write(a, "x"));
        assertEquals(List.of(a, b), list(dir));
    }

    @Test
    void aPictureIsSavedAtomicallyThroughItsLinkWithItsMode(@TempDir Path dir) throws IOException {
        assumeTrue(posix(), "POSIX permissions");
        Path real = Files.createDirectories(dir.resolve("pictures")).resolve("plot.png");
        Files.writeString(real, "an older picture");
        Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rw-rw-r--"));
        Path link = Files.createSymbolicLink(dir.resolve("plot.png"), Path.of("pictures", "plot.png"));
        BufferedImage img = new BufferedImage(30, 20, BufferedImage.TYPE_INT_RGB);
        img.setRGB(3, 4, 0x123456);
        AtomicFiles.writePng(link, img);
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        BufferedImage back = ImageIO.read(real.toFile());
        assertEquals(30, back.getWidth());
        assertEquals(0x123456, back.getRGB(3, 4) & 0xffffff, "the picture is the one given");
        assertEquals("rw-rw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
        assertEquals(List.of(real), list(real.getParent()), "no temporary file is left");
    }

    private static long findDeadPid() {
        for (long pid = 4_000_000; pid > 1000; pid -= 7919) {
            if (ProcessHandle.of(pid).isEmpty()) {
                return pid;
            }
        }
        throw new AssertionError("no unused process id");
    }
}
