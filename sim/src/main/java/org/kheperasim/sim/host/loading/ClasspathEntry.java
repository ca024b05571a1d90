package org.kheperasim.sim.host.loading;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.channels.Channels;
import java.nio.channels.SeekableByteChannel;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.CodeSigner;
import java.security.CodeSource;
import java.security.ProtectionDomain;
import java.util.Locale;
import java.util.Set;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.zip.ZipFile;

/**
 * One entry of a controller's classpath, a directory or a jar file: where {@link ControllerClassLoader}
 * finds the controller's class files and its resources. A name never reaches outside the entry: in a
 * directory, a file is found only when its real path (every symbolic link followed) lies inside the
 * directory's own real path, so a link to {@code /etc/passwd}, to {@code /proc} or to another
 * student's folder is no resource of the controller's; and it is read without following a link
 * again. Nothing larger than {@link #MAX_BYTES} is read: its size is checked first.
 */
abstract class ClasspathEntry implements Closeable {
    /** The largest class file or resource read into memory (64 MiB; the largest real class files are a few MB). */
    static final long MAX_BYTES = 64L << 20;

    final ProtectionDomain domain;

    /** A class file or resource larger than {@link #MAX_BYTES}: not read. */
    static final class TooLarge extends IOException {
        private static final long serialVersionUID = 1L;

        TooLarge(String where, long size) {
            super(where + ": " + bytes(size) + ", more than the " + bytes(MAX_BYTES) + " a class file or resource may"
                    + " have (is it one? remove it, or keep large data out of the controller's folder)");
        }
    }

    /** @return a size for a message: {@code 3.0 GB}, {@code 64 MB}, {@code 812 bytes} */
    static String bytes(long size) {
        if (size >= 1L << 30) {
            return String.format(Locale.ROOT, "%.1f GB", size / (double) (1L << 30));
        }
        if (size >= 1L << 20) {
            return String.format(Locale.ROOT, "%d MB", size >> 20);
        }
        return size + " bytes";
    }

    /** Read at most {@link #MAX_BYTES} (a file may grow after its size was looked at). */
    static byte[] readBounded(InputStream in, String where) throws IOException {
        byte[] bytes = in.readNBytes((int) MAX_BYTES + 1);
        if (bytes.length > MAX_BYTES) {
            throw new TooLarge(where, bytes.length);
        }
        return bytes;
    }

    ClasspathEntry(Path path) {
        this.domain = new ProtectionDomain(new CodeSource(toUrl(path.toUri()), (CodeSigner[]) null), null);
    }

    /**
     * @throws IllegalArgumentException when the entry is neither a directory nor a file
     * @throws UncheckedIOException when a jar file cannot be opened
     */
    static ClasspathEntry open(Path entry) {
        Path path = entry.toAbsolutePath().normalize();
        if (Files.isDirectory(path)) {
            return new DirectoryEntry(path);
        }
        if (Files.isRegularFile(path)) {
            return new JarFileEntry(path);
        }
        throw new IllegalArgumentException("Classpath entry " + entry + " is neither a directory nor a jar file");
    }

    /** @return the resource's bytes, or null when this entry has no such resource */
    abstract byte[] read(String resource) throws IOException;

    /** @return the resource's URL, or null when this entry has no such resource */
    abstract URL url(String resource);

    /** @return where the resource is, for messages */
    abstract String describe(String resource);

    private static URL toUrl(URI uri) {
        try {
            return uri.toURL();
        } catch (MalformedURLException e) {
            throw new IllegalStateException("No URL for " + uri, e);
        }
    }

    private static final class DirectoryEntry extends ClasspathEntry {
        private final Path directory;
        /** The directory's real path (links followed), or null when it has none (it is gone). */
        private final Path real;

        DirectoryEntry(Path directory) {
            super(directory);
            this.directory = directory;
            Path r;
            try {
                r = directory.toRealPath();
            } catch (IOException e) {
                r = null;
            }
            this.real = r;
        }

        /**
         * The resource's real file, or null when it is missing, not a regular file, or its name or a link
         * on its way points outside the directory.
         */
        private Path file(String resource) {
            Path file = directory.resolve(resource).normalize();
            if (real == null || !file.startsWith(directory)) {
                return null;
            }
            Path resolved;
            try {
                resolved = file.toRealPath();
            } catch (IOException | SecurityException e) {
                return null;
            }
            return resolved.startsWith(real) && Files.isRegularFile(resolved, LinkOption.NOFOLLOW_LINKS)
                    ? resolved : null;
        }

        @Override
        byte[] read(String resource) throws IOException {
            Path file = file(resource);
            if (file == null) {
                return null;
            }
            try (SeekableByteChannel channel = Files.newByteChannel(file, Set.of(StandardOpenOption.READ,
                    LinkOption.NOFOLLOW_LINKS))) {
                if (channel.size() > MAX_BYTES) {
                    throw new TooLarge(describe(resource), channel.size());
                }
                return readBounded(Channels.newInputStream(channel), describe(resource));
            } catch (TooLarge e) {
                throw e;
            } catch (IOException e) {
                throw new IOException("cannot read " + file + ": " + e, e);
            }
        }

        @Override
        URL url(String resource) {
            Path file = file(resource);
            return file == null ? null : toUrl(file.toUri());
        }

        @Override
        String describe(String resource) {
            return directory.resolve(resource).toString();
        }

        @Override
        public void close() {
        }
    }

    private static final class JarFileEntry extends ClasspathEntry {
        private final Path path;
        private final JarFile jar;

        JarFileEntry(Path path) {
            super(path);
            this.path = path;
            try {
                this.jar = new JarFile(path.toFile(), false, ZipFile.OPEN_READ, JarFile.runtimeVersion());
            } catch (IOException e) {
                throw new UncheckedIOException("Cannot open classpath jar " + path + ": " + e.getMessage(), e);
            }
        }

        private JarEntry entry(String resource) {
            JarEntry entry = jar.getJarEntry(resource);
            return entry == null || entry.isDirectory() ? null : entry;
        }

        @Override
        byte[] read(String resource) throws IOException {
            JarEntry entry = entry(resource);
            if (entry == null) {
                return null;
            }
            if (entry.getSize() > MAX_BYTES) {
                throw new TooLarge(describe(resource), entry.getSize());
            }
            try (InputStream in = jar.getInputStream(entry)) {
                return readBounded(in, describe(resource));
            } catch (TooLarge e) {
                throw e;
            } catch (IOException e) {
                throw new IOException("cannot read " + describe(resource) + ": " + e, e);
            }
        }

        @Override
        URL url(String resource) {
            if (entry(resource) == null) {
                return null;
            }
            try {
                return toUrl(new URI("jar", path.toUri() + "!/" + resource, null));
            } catch (URISyntaxException e) {
                throw new IllegalStateException("No URL for " + describe(resource), e);
            }
        }

        @Override
        String describe(String resource) {
            return path + "!/" + resource;
        }

        @Override
        public void close() throws IOException {
            jar.close();
        }
    }
}
