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
 * Replies are as long as the numbers they carry ({@link #replyChars}), so the poll cycle runs
 * faster while the values are small: at 38400 baud about 40 cycles/s with typical values (two-digit
 * proximity, three-digit light, four-digit counters), 28 with every value at its longest.
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
    /**
     * The host's own time between the last character of a reply and the first of its next command:
     * robot-link reading the line, storing the values and writing the next command through the
     * operating system's serial (or TCP) stack. Measured on our Linux machines at 0.3 to 0.5 ms per
     * exchange over a pty and over TCP; a USB-serial adapter adds its own latency timer (1 ms when
     * tuned, 16 ms by default on FTDI chips), so a real lab may poll slower still.
     */
    public static final long HOST_GAP_NANOS = 300_000L;
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

    /**
     * Characters of the reply to a poll step that carries {@code values}, CR LF included: the
     * robot writes each value in decimal with no padding ({@code n,15,22,...}), so a reply is as
     * long as its numbers are.
     *
     * @param step the poll step
     * @param values the values in the reply (8 for N and O, 2 for H)
     * @return the reply's length on the wire, characters
     */
    public static int replyChars(PollStep step, int[] values) {
        int chars = 1 + values.length + 2; // the letter, a comma before each value, CR LF
        for (int v : values) {
            chars += decimalLength(v);
        }
        return chars;
    }

    /** @return how many characters {@code v} takes in decimal, its sign included */
    static int decimalLength(int v) {
        if (v < 0) {
            return v == Integer.MIN_VALUE ? 11 : 1 + decimalLength(-v);
        }
        int n = 1;
        for (long p = 10; p <= v; p *= 10) {
            n++;
        }
        return n;
    }

    /**
     * @param step a poll step
     * @return the time from the end of the previous reply until the robot acts on this step's
     *     command: the host's gap ({@link #HOST_GAP_NANOS}), the command's characters and the
     *     robot's turnaround, ns
     */
    public long commandNanos(PollStep step) {
        return HOST_GAP_NANOS + wireNanos(step.commandChars()) + turnaroundNanos;
    }

    /**
     * @param step a poll step
     * @param values the values its reply carries
     * @return the reply's time on the wire, ns
     */
    public long replyNanos(PollStep step, int[] values) {
        return wireNanos(replyChars(step, values));
    }

    /**
     * The time one poll cycle takes when its replies carry these values: each exchange is its
     * command, the turnaround and its reply, each as long as it really is.
     *
     * @param proximity the eight proximity values
     * @param light the eight light values
     * @param counters the two position counters
     * @return the cycle's time, ns
     */
    public long pollCycleNanos(int[] proximity, int[] light, int[] counters) {
        return commandNanos(PollStep.PROXIMITY) + replyNanos(PollStep.PROXIMITY, proximity)
                + commandNanos(PollStep.LIGHT) + replyNanos(PollStep.LIGHT, light)
                + commandNanos(PollStep.ENCODERS) + replyNanos(PollStep.ENCODERS, counters);
    }

    /** @return the time one whole poll cycle (N, O, H) takes with every reply at its longest, ns (an upper bound) */
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
        int chars = 2 + decimalLength(left) + 1 + decimalLength(right) + 1;
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
