package org.kheperasim.link.io;

import java.io.IOException;

/** The far end of a link has gone: the cable was pulled, the adapter unplugged, the server closed. */
public class LinkClosedException extends IOException {
    /** @param message what has gone and what to check */
    public LinkClosedException(String message) {
        super(message);
    }
}
