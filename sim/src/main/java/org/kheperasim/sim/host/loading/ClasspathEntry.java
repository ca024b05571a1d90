package org.kheperasim.sim.host.loading;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSigner;
import java.security.CodeSource;
import java.security.ProtectionDomain;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.zip.ZipFile;

/**
 * One entry of a controller's classpath, a directory or a jar file: where {@link ControllerClassLoader}
 * finds the controller's class files and its resources. A name never reaches outside the entry.
 */
abstract class ClasspathEntry implements Closeable {
    final ProtectionDomain domain;

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

        DirectoryEntry(Path directory) {
            super(directory);
            this.directory = directory;
        }

        /** The resource's file, or null when it is missing or its name points outside the directory. */
        private Path file(String resource) {
            Path file = directory.resolve(resource).normalize();
            return file.startsWith(directory) && Files.isRegularFile(file) ? file : null;
        }

        @Override
        byte[] read(String resource) throws IOException {
            Path file = file(resource);
            if (file == null) {
                return null;
            }
            try {
                return Files.readAllBytes(file);
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
            try (InputStream in = jar.getInputStream(entry)) {
                return in.readAllBytes();
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
