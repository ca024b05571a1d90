package org.kheperasim.link.timing;

import java.util.List;

/**
 * How long the serial link between host and Khepera takes, shared by the simulator and robot-link
 * so that a controller sees sensor values at the same rate and motor commands take effect after
 * the same delay on both.
 *
 * <p>A character is 11 bits on the wire (1 start, 8 data, 2 stop bits), so one character takes
 * 1.146 ms at 9600 baud and 0.286 ms at 38400. An exchange is the command's characters, the
 * robot's turnaround (the time it takes to act and start replying), then the reply's characters.
 *
 * @param baud line speed, bits per second (the Khepera uses 9600 to 115200)
 * @param bitsPerChar bits per character on the wire, 11 for 8 data bits and 2 stop bits
 * @param turnaroundNanos the robot's time between the end of a command and the start of its reply
 */
public record LinkTiming(int baud, int bitsPerChar, long turnaroundNanos) {

    /** The Khepera I's fastest setting, and the default. */
    public static final int DEFAULT_BAUD = 38400;
    /** 1 start + 8 data + 2 stop bits. */
    public static final int DEFAULT_BITS_PER_CHAR = 11;
    /** Default robot turnaround: 0.5 ms (not documented by K-Team; a setting). */
    public static final long DEFAULT_TURNAROUND_NANOS = 500_000L;
    /** The poll cycle, in order. */
    public static final List<PollStep> POLL_CYCLE = List.of(PollStep.values());

    /** Validates the settings. */
    public LinkTiming {
        if (baud < 300 || baud > 1_000_000) {
            throw new IllegalArgumentException("baud " + baud + " is not a serial line speed; the Khepera"
                    + " uses 9600, 19200, 38400, 57600 or 115200");
        }
        if (bitsPerChar < 7 || bitsPerChar > 12) {
            throw new IllegalArgumentException("bits per character " + bitsPerChar + " must lie in 7..12");
        }
        if (turnaroundNanos < 0) {
            throw new IllegalArgumentException("turnaround must not be negative: " + turnaroundNanos);
        }
    }

    /** @param baud line speed, bits per second @return the Khepera's framing at that speed */
    public static LinkTiming atBaud(int baud) {
        return new LinkTiming(baud, DEFAULT_BITS_PER_CHAR, DEFAULT_TURNAROUND_NANOS);
    }

    /** @return the default link: 38400 baud, 8 data bits, 2 stop bits */
    public static LinkTiming defaults() {
        return atBaud(DEFAULT_BAUD);
    }

    /** @param chars characters @return their time on the wire, ns */
    public long wireNanos(int chars) {
        return (long) chars * bitsPerChar * 1_000_000_000L / baud;
    }

    /**
     * @param commandChars characters of the command, terminator included
     * @param replyChars characters of the reply, CR LF included
     * @return the time from the first command character to the last reply character, ns
     */
    public long exchangeNanos(int commandChars, int replyChars) {
        return wireNanos(commandChars + replyChars) + turnaroundNanos;
    }

    /** @param step a poll step @return its exchange time, ns */
    public long exchangeNanos(PollStep step) {
        return exchangeNanos(step.commandChars(), step.replyChars());
    }

    /** @return the time one whole poll cycle (N, O, H) takes, ns */
    public long pollCycleNanos() {
        long sum = 0;
        for (PollStep s : POLL_CYCLE) {
            sum += exchangeNanos(s);
        }
        return sum;
    }

    /**
     * When a set-speed command {@code D,l,r} takes effect after it is issued: its characters reach
     * the robot and the robot acts on them.
     *
     * @param left left speed, units
     * @param right right speed, units
     * @return delay from issuing the command to the wheels changing, ns
     */
    public long speedCommandDelayNanos(int left, int right) {
        int chars = 2 + Integer.toString(left).length() + 1 + Integer.toString(right).length() + 1;
        return wireNanos(chars) + turnaroundNanos;
    }

    /**
     * When a position-counter command {@code G,l,r} takes effect.
     *
     * @param left new left counter
     * @param right new right counter
     * @return delay from issuing the command to the counters changing, ns
     */
    public long setPositionDelayNanos(int left, int right) {
        return speedCommandDelayNanos(left, right);
    }
}
