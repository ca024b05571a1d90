package org.kheperasim.link.timing;

/**
 * One exchange of the poll cycle that keeps a controller's view of the robot fresh, in the order
 * the cycle runs them. The robot-link poll loop sends exactly these commands; the simulator delivers
 * sensor values on the same schedule, so code tuned in one behaves the same in the other.
 *
 * <p>{@link #replyChars()} is the longest each reply can be (every value at its widest), an upper
 * bound; a real reply is as long as its numbers ({@link LinkTiming#replyChars(PollStep, int[])}).
 */
public enum PollStep {
    /** {@code N}: the eight proximity values; reply {@code n,v0,...,v7} with 4-digit values. */
    PROXIMITY('N', 2 + 8 * 4 + 7 + 2),
    /** {@code O}: the eight ambient-light values; reply {@code o,v0,...,v7}. */
    LIGHT('O', 2 + 8 * 4 + 7 + 2),
    /** {@code H}: the two wheel position counters; reply {@code h,l,r} with 11-character values. */
    ENCODERS('H', 2 + 11 + 1 + 11 + 2);

    private final char command;
    private final int replyChars;

    PollStep(char command, int replyChars) {
        this.command = command;
        this.replyChars = replyChars;
    }

    /** @return the protocol letter sent */
    public char command() {
        return command;
    }

    /** @return characters on the wire for the command: the letter and one line terminator */
    public int commandChars() {
        return 2;
    }

    /** @return characters of the longest reply, including its CR LF */
    public int replyChars() {
        return replyChars;
    }
}
