package org.kheperasim.sim.host;

/** Where console lines go: standard output for the command line, the console panel in the window. */
@FunctionalInterface
public interface ConsoleSink {
    /** @param line a line to show */
    void accept(ConsoleLine line);
}
