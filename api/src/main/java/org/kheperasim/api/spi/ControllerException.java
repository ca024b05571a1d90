package org.kheperasim.api.spi;

/** A controller class cannot be loaded, checked or constructed; the message says which and why. */
public class ControllerException extends RuntimeException {
    /** @param message what is wrong and how to fix it */
    public ControllerException(String message) {
        super(message);
    }

    /**
     * @param message what is wrong and how to fix it
     * @param cause the underlying failure
     */
    public ControllerException(String message, Throwable cause) {
        super(message, cause);
    }
}
