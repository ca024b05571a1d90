package org.kheperasim.sim.host;

/**
 * A class loader that may contain the controller code it loads (rewrite its escapes and thread
 * calls onto the host's hooks): the controller class loader of {@code host.loading} is one. The
 * host asks a controller's loader through this interface, so that it knows nothing of the loading
 * package, which sits above it (the loading package names the host's hooks in the code it rewrites).
 */
public interface ContainingLoader {
    /** @return true when the code this loader defines is contained */
    boolean contained();
}
