package org.kheperasim.sim.files;

import java.awt.image.RenderedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.GroupPrincipal;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFileAttributes;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;

/**
 * The one way the simulator saves a file (arenas, settings, edit logs, run recordings, web pages, the grade
 * report and its pictures, the window's plot exports): a reader
 * never sees half a file, and a failed save leaves the old file as it was.
 *
 * <ol>
 *   <li>A symbolic link is followed to the file it names: the link stays a link and its target
 *       gets the new content.</li>
 *   <li>The bytes go to a temporary file in the target's own folder ({@code .NAME.PID-N.tmp}),
 *       created with the process's default permissions, or with the permissions (and, where
 *       allowed, the group) of the file being replaced; then it is flushed to the disk.</li>
 *   <li>One rename puts it in place, and the folder is flushed too where the system allows it, so
 *       the rename survives a power cut.</li>
 *   <li>On any failure the temporary file is deleted. Temporary files left by a save that was
 *       killed (kill -9, power cut) are deleted by the next save to the same file, once the
 *       process that made them has gone.</li>
 * </ol>
 */
public final class AtomicFiles {

    private static final System.Logger LOG = System.getLogger(AtomicFiles.class.getName());
    private static final AtomicLong COUNTER = new AtomicLong();
    private static final int MAX_LINKS = 40;

    private AtomicFiles() {
    }

    /**
     * Renames a finished file, atomically where the file system can (a working file kept under another name).
     *
     * @param from the file
     * @param to   its new name, in the same folder; replaced if it exists
     * @throws IOException naming what failed
     */
    public static void rename(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /**
     * Saves text as UTF-8, atomically.
     *
     * @param file where, possibly through a symbolic link, in an existing folder
     * @param text the whole content
     * @throws IOException naming what failed; the old file, if any, is unchanged
     */
    public static void write(Path file, String text) throws IOException {
        write(file, text.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Saves bytes atomically.
     *
     * @param file  where, possibly through a symbolic link, in an existing folder
     * @param bytes the whole content
     * @throws IOException naming what failed; the old file, if any, is unchanged
     */
    public static void write(Path file, byte[] bytes) throws IOException {
        Path target = resolveLinks(file.toAbsolutePath());
        Path dir = target.getParent();
        removeStaleTemporaries(dir, target.getFileName().toString());
        Path tmp = dir.resolve(temporaryName(target.getFileName().toString(), ProcessHandle.current().pid(),
                COUNTER.incrementAndGet()));
        boolean done = false;
        try {
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
                ByteBuffer buf = ByteBuffer.wrap(bytes);
                while (buf.hasRemaining()) {
                    ch.write(buf);
                }
                ch.force(true);
            }
            copyPermissions(target, tmp);
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            done = true;
            syncDirectory(dir);
        } finally {
            if (!done) {
                deleteQuietly(tmp);
            }
        }
    }

    /**
     * Saves an image as PNG, atomically: it is encoded in memory first, so a failed encoding leaves
     * the old file as it was too.
     *
     * @param file  where, possibly through a symbolic link, in an existing folder
     * @param image the picture
     * @throws IOException naming what failed, also when this Java runtime has no PNG writer
     */
    public static void writePng(Path file, RenderedImage image) throws IOException {
        ByteArrayOutputStream png = new ByteArrayOutputStream(1 << 16);
        if (!ImageIO.write(image, "png", png)) {
            throw new IOException("cannot write " + file + ": no PNG writer in this Java runtime");
        }
        write(file, png.toByteArray());
    }

    /**
     * Follows symbolic links to the file they finally name (which need not exist yet).
     *
     * @param file an absolute path
     * @return the path the content really goes to
     * @throws IOException when the links form a loop or cannot be read
     */
    static Path resolveLinks(Path file) throws IOException {
        Path p = file;
        for (int i = 0; i < MAX_LINKS && Files.isSymbolicLink(p); i++) {
            Path link = Files.readSymbolicLink(p);
            p = p.getParent().resolve(link).normalize();
        }
        if (Files.isSymbolicLink(p)) {
            throw new FileSystemException(file.toString(), null, "more than " + MAX_LINKS
                    + " symbolic links in a row (a loop?)");
        }
        return p;
    }

    /** @return the temporary file's name for a save of {@code name} by process {@code pid} */
    static String temporaryName(String name, long pid, long n) {
        return "." + name + "." + pid + "-" + n + ".tmp";
    }

    private static void copyPermissions(Path from, Path to) {
        PosixFileAttributeView fromView = Files.getFileAttributeView(from, PosixFileAttributeView.class);
        PosixFileAttributeView toView = Files.getFileAttributeView(to, PosixFileAttributeView.class);
        if (fromView == null || toView == null) {
            return;
        }
        PosixFileAttributes old;
        try {
            old = fromView.readAttributes();
        } catch (NoSuchFileException e) {
            return;
        } catch (IOException e) {
            LOG.log(System.Logger.Level.DEBUG,
                    "cannot read the permissions of " + from + "; the saved file gets the defaults", e);
            return;
        }
        try {
            toView.setPermissions(old.permissions());
        } catch (IOException e) {
            LOG.log(System.Logger.Level.WARNING, "cannot give " + to + " the permissions of " + from + ": " + e);
        }
        try {
            GroupPrincipal group = old.group();
            if (!group.equals(Files.readAttributes(to, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS).group())) {
                toView.setGroup(group);
            }
        } catch (IOException e) {
            // Only the group's owner or root may hand a file to another group; the permissions are kept.
            LOG.log(System.Logger.Level.DEBUG, "cannot keep the group of " + from + ": " + e);
        }
    }

    /** Flushes a folder's entries (the rename) to the disk; not every system can open a folder. */
    private static void syncDirectory(Path dir) {
        try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
            ch.force(true);
        } catch (IOException | UnsupportedOperationException e) {
            LOG.log(System.Logger.Level.DEBUG, "cannot flush folder " + dir + " (normal on Windows): " + e);
        }
    }

    /** Deletes {@code .NAME.PID-N.tmp} files of earlier saves whose process no longer runs. */
    private static void removeStaleTemporaries(Path dir, String name) {
        String prefix = "." + name + ".";
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, p -> {
            String n = p.getFileName().toString();
            return n.startsWith(prefix) && n.endsWith(".tmp");
        })) {
            for (Path p : files) {
                String middle = p.getFileName().toString().substring(prefix.length());
                int dash = middle.indexOf('-');
                if (dash <= 0) {
                    continue;
                }
                long pid;
                try {
                    pid = Long.parseLong(middle.substring(0, dash));
                } catch (NumberFormatException e) {
                    continue;
                }
                if (pid != ProcessHandle.current().pid() && ProcessHandle.of(pid).isEmpty()) {
                    deleteQuietly(p);
                }
            }
        } catch (IOException e) {
            LOG.log(System.Logger.Level.DEBUG, "cannot look for leftovers of earlier saves in " + dir + ": " + e);
        }
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            LOG.log(System.Logger.Level.WARNING, "cannot delete the temporary file " + p + ": " + e);
        }
    }
}
