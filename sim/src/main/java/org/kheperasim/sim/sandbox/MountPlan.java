package org.kheperasim.sim.sandbox;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The file tree inside a box, as bubblewrap arguments: an empty root, and in it only the host paths
 * given, each at its own path, with the symbolic links on the way to it (so {@code /lib64/ld-linux…}
 * reaches the loader through {@code /lib64 -> usr/lib64} as on the host) and the folders that hold
 * them, readable by anyone (bubblewrap would make them owner-only, which an unprivileged user in the
 * box could not enter).
 */
final class MountPlan {
    private final TreeSet<Path> dirs = new TreeSet<>();
    private final Map<Path, Path> links = new TreeMap<>();
    private final Map<Path, Bind> binds = new LinkedHashMap<>();
    private final List<String> head = new ArrayList<>();

    private record Bind(Path source, Path dest, boolean writable) {
    }

    /**
     * Make a host file or folder visible at its own path, read-only.
     *
     * @param hostPath an absolute path that exists
     */
    void readOnly(Path hostPath) {
        Path real = resolve(hostPath.toAbsolutePath());
        binds.putIfAbsent(real, new Bind(real, real, false));
    }

    /**
     * Make a host file or folder visible at another path.
     *
     * @param hostPath an existing path
     * @param dest     where it appears in the box (its folders are made)
     * @param writable true to let the box write it
     */
    void bind(Path hostPath, Path dest, boolean writable) {
        Path real;
        try {
            real = hostPath.toRealPath();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot find " + hostPath + " to put it in the sandbox: "
                    + e.getMessage(), e);
        }
        folders(dest.getParent());
        binds.put(dest, new Bind(real, dest, writable));
    }

    /**
     * @param args bubblewrap arguments applied before every folder, link and bind (a tmpfs, /proc, /dev):
     *     a bind under {@code /tmp} must come after the tmpfs there, or the tmpfs would hide it
     */
    void first(String... args) {
        head.addAll(List.of(args));
    }

    /** Make a folder (and its parents) in the box, readable by anyone. */
    void folders(Path dir) {
        for (Path d = dir; d != null && d.getParent() != null; d = d.getParent()) {
            dirs.add(d);
        }
    }

    /** @return the bubblewrap arguments: the mounts given first, folders, links, then binds, in that order */
    List<String> args() {
        List<String> out = new ArrayList<>(head);
        for (Path d : dirs) {
            if (!links.containsKey(d)) {
                out.addAll(List.of("--perms", "0755", "--dir", d.toString()));
            }
        }
        links.forEach((at, target) -> out.addAll(List.of("--symlink", target.toString(), at.toString())));
        for (Bind b : binds.values()) {
            out.addAll(List.of(b.writable ? "--bind" : "--ro-bind", b.source.toString(), b.dest.toString()));
        }
        return out;
    }

    /**
     * Walk a path as the kernel would: every symbolic link met on the way is kept (to be made in the
     * box), and the walk goes on at its target; every real folder on the way is kept too.
     *
     * @return the real path
     */
    private Path resolve(Path p) {
        Path cur = p.getRoot();
        for (Path name : p) {
            if (name.toString().equals("..")) {
                cur = cur.getParent() == null ? cur : cur.getParent();
                continue;
            }
            if (name.toString().equals(".")) {
                continue;
            }
            Path next = cur.resolve(name);
            if (Files.isSymbolicLink(next)) {
                try {
                    Path target = Files.readSymbolicLink(next);
                    links.putIfAbsent(next, target);
                    folders(cur);
                    cur = resolve(cur.resolve(target));
                } catch (IOException e) {
                    throw new UncheckedIOException("cannot read the link " + next + ": " + e.getMessage(), e);
                }
            } else {
                folders(cur);
                cur = next;
            }
        }
        return cur;
    }
}
