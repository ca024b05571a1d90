package org.kheperasim.link.session;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.LongAdder;
import org.kheperasim.link.io.Link;
import org.kheperasim.link.io.LinkClosedException;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.Reply;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.protocol.dialect.KheperaDialect;
import org.kheperasim.link.timing.LinkTiming;

/**
 * One conversation with a robot. The host is master: it sends one command and waits for its reply
 * before the next ({@link #exchange} is synchronized). Before each command, whatever is waiting on
 * the line (a late reply, a boot banner, noise) is thrown away; while waiting, lines that do not
 * start with the command's reply letter are skipped (resynchronisation). A command with no fitting
 * reply in time is sent again, up to {@link Options#retries} more times.
 */
public final class Session implements AutoCloseable {

    /**
     * @param replyTimeoutMillis how long to wait for a reply beyond its wire time, ms (clients use 100–500)
     * @param retries how many more times to send a command that got no reply
     * @param bannerQuietMillis at open, input stops counting as a boot banner after this much silence, ms
     * @param bannerMaxMillis at open, the longest time spent throwing away a banner, ms
     */
    public record Options(long replyTimeoutMillis, int retries, long bannerQuietMillis, long bannerMaxMillis) {
        /** @return 300 ms timeout, 3 retries, 200 ms of quiet ends a banner, at most 3 s */
        public static Options defaults() {
            return new Options(300, 3, 200, 3000);
        }

        /** Checks the values. */
        public Options {
            if (replyTimeoutMillis < 1 || retries < 0 || bannerQuietMillis < 0 || bannerMaxMillis < 0) {
                throw new IllegalArgumentException("reply timeout must be at least 1 ms and retries not negative: "
                        + replyTimeoutMillis + " ms, " + retries + " retries");
            }
        }

        /** @param millis reply timeout, ms @return these options with it */
        public Options withReplyTimeout(long millis) {
            return new Options(millis, retries, bannerQuietMillis, bannerMaxMillis);
        }

        /** @param n retries @return these options with them */
        public Options withRetries(int n) {
            return new Options(replyTimeoutMillis, n, bannerQuietMillis, bannerMaxMillis);
        }
    }

    /** The robot's versions from the {@code B} handshake. @param bios BIOS version @param protocol protocol version */
    public record Versions(String bios, String protocol) {
    }

    /**
     * What the session has seen so far.
     *
     * @param exchanges commands answered
     * @param retries commands sent again after no fitting reply in time
     * @param skippedLines lines thrown away while waiting (stale replies, banners, noise)
     * @param discardedChars characters thrown away before commands (late replies, noise)
     * @param meanRoundTripNanos mean time from sending a command to its reply, ns
     * @param maxRoundTripNanos longest such time, ns
     */
    public record Stats(long exchanges, long retries, long skippedLines, long discardedChars,
            long meanRoundTripNanos, long maxRoundTripNanos) {
    }

    private volatile Transcript transcript;
    private final Link link;
    private final Options options;
    private final LinkTiming timing;
    private final Dialect dialect;
    private final LongAdder exchanges = new LongAdder();
    private final LongAdder retries = new LongAdder();
    private final LongAdder skippedLines = new LongAdder();
    private final LongAdder discardedChars = new LongAdder();
    private final LongAdder foreignLines = new LongAdder();
    private final LongAdder boots = new LongAdder();
    /** Characters of the replies received, and how many replies, by the command's letter (A..Z). */
    private final long[] repliedChars = new long[26];
    private final long[] replies = new long[26];
    private long rttSum;
    private long rttMax;
    private volatile String lastSent;
    private volatile boolean lost;

    /**
     * @param link the open link
     * @param timing the line's timing, to allow each reply its wire time on top of the timeout
     * @param options timeouts and retries
     */
    public Session(Link link, LinkTiming timing, Options options) {
        this(link, timing, options, KheperaDialect.KHEPERA1);
    }

    /**
     * @param link the open link
     * @param timing the line's timing, to allow each reply its wire time on top of the timeout
     * @param options timeouts and retries
     * @param dialect the robot's protocol: its version command, replies, error replies and banner
     */
    public Session(Link link, LinkTiming timing, Options options, Dialect dialect) {
        this.link = link;
        this.timing = timing;
        this.options = options;
        this.dialect = dialect;
        this.lastSent = null;
    }

    /** @return the robot's protocol */
    public Dialect dialect() {
        return dialect;
    }

    /** @return the link */
    public Link link() {
        return link;
    }

    /** @return the options */
    public Options options() {
        return options;
    }

    /**
     * Start the conversation: throw away a boot banner and stale input, then ask the versions.
     *
     * @return the robot's versions
     * @throws SessionException naming the link and what to check when the robot does not answer
     */
    public synchronized Versions open() throws SessionException {
        Command b = dialect.version();
        try {
            long end = System.nanoTime() + options.bannerMaxMillis() * 1_000_000L;
            while (System.nanoTime() < end) {
                String line = link.readLine(options.bannerQuietMillis());
                if (line == null) {
                    break;
                }
                skippedLines.increment();
            }
        } catch (IOException e) {
            throw lost(b, e);
        }
        Reply r;
        try {
            r = exchange(b);
        } catch (SessionException e) {
            if (e.kind() == SessionException.Kind.NO_REPLY && !(dialect instanceof KheperaDialect)) {
                throw new SessionException(e.kind(), b,
                        "the " + dialect.robot() + " on " + link.describe() + " does not"
                        + " answer the version command '" + b.encode() + "'. Check that it is switched on, that its"
                        + " selector is on the ASCII protocol (SerCom), that a Bluetooth port is paired, that --baud"
                        + " matches and that --dialect " + dialect.name() + " is its protocol", e);
            }
            if (e.kind() == SessionException.Kind.NO_REPLY) {
                throw new SessionException(e.kind(), b, "the robot on " + link.describe() + " does not answer the"
                        + " version command 'B'. Check that it is switched on, that its mode jumper is on a protocol"
                        + " mode (1-3, or 8-9 on a Khepera II) and that --baud matches that mode", e);
            }
            throw e;
        }
        return new Versions(r.values().get(0), r.values().size() > 1 ? r.values().get(1) : "");
    }

    /** Told of every line the session sends and receives (a run's recording keeps them all). */
    public interface Transcript {
        /**
         * @param nanos when, {@link System#nanoTime()}
         * @param sent true for a line sent to the robot, false for one received
         * @param text the line, without its end
         */
        void line(long nanos, boolean sent, String text);
    }

    /** @param t told of every line from now on, or null for none */
    public void transcript(Transcript t) {
        transcript = t;
    }

    private void told(boolean sent, String text) {
        Transcript t = transcript;
        if (t != null) {
            t.line(System.nanoTime(), sent, text);
        }
    }

    /**
     * Send a command and wait for its reply, with retries.
     *
     * @param command the command
     * @return its reply
     * @throws SessionException naming the command: no reply, an error reply, or the link gone
     */
    public synchronized Reply exchange(Command command) throws SessionException {
        String line = command.encode();
        // A reply's wire time: 64 characters cover every reply but the long ones (the K213's image of
        // 64 numbers), which take up to 4 characters a value.
        int replyChars = StrictMath.max(64, 8 + 4 * command.replyValueCount());
        long waitNanos = options.replyTimeoutMillis() * 1_000_000L
                + timing.exchangeNanos(line.length() + 1, replyChars);
        ProtocolException refusal = null;
        int tries = options.retries() + 1;
        for (int attempt = 0; attempt < tries; attempt++) {
            if (attempt > 0) {
                retries.increment();
            }
            long sent;
            try {
                discardedChars.add(link.discardInput());
                lastSent = line;
                link.writeLine(line);
                sent = System.nanoTime();
                told(true, line);
                long deadline = sent + waitNanos;
                while (true) {
                    long left = deadline - System.nanoTime();
                    String got = left <= 0 ? null : link.readLine(Math.max(1, left / 1_000_000L));
                    if (got == null) {
                        break;
                    }
                    told(false, got);
                    try {
                        Reply reply = dialect.parseReply(command, got);
                        record(System.nanoTime() - sent);
                        countReply(line, got);
                        return reply;
                    } catch (ProtocolException e) {
                        skippedLines.increment();
                        if (!looksLikeReply(got)) {
                            foreignLines.increment();
                            if (dialect.looksLikeBanner(got)) {
                                boots.increment();
                            }
                        }
                        if (e.kind() == ProtocolException.Kind.COMMAND_NOT_FOUND
                                || e.kind() == ProtocolException.Kind.ROBOT_ERROR) {
                            refusal = e;
                        }
                        // Noise before our command can draw an error reply too: read on until the time is up.
                    }
                }
            } catch (IOException e) {
                throw lost(command, e);
            }
            if (refusal != null) {
                throw new SessionException(SessionException.Kind.REFUSED, command,
                        refusal.getMessage() + " (on " + link.describe() + ")", refusal);
            }
        }
        throw new SessionException(SessionException.Kind.NO_REPLY, command, "no reply to '" + line + "' from "
                + link.describe() + " after " + tries + " tries of " + waitNanos / 1_000_000L + " ms each; check"
                + " that the robot is on and the cable is in, or give a longer --timeout", null);
    }

    /**
     * Send a command and expect no answer, ignoring failure: the last word to a robot that may no
     * longer answer (the safety stop when the link is failing).
     *
     * @param command the command to send
     * @return true when it was written to the link
     */
    public synchronized boolean sendBlind(Command command) {
        try {
            lastSent = command.encode();
            link.writeLine(lastSent);
            told(true, lastSent);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * Send a raw line and collect what comes back (the console): lines until {@code quietMillis}
     * pass without one, for at most {@code maxMillis}.
     *
     * @param line any text
     * @param quietMillis silence that ends the reply, ms
     * @param maxMillis the longest wait, ms
     * @return the lines received
     * @throws IOException when the link has gone
     */
    public synchronized List<String> raw(String line, long quietMillis, long maxMillis) throws IOException {
        discardedChars.add(link.discardInput());
        lastSent = line;
        link.writeLine(line);
        List<String> got = new ArrayList<>();
        long end = System.nanoTime() + maxMillis * 1_000_000L;
        long wait = options.replyTimeoutMillis() + timing.wireNanos(line.length() + 80) / 1_000_000L;
        while (System.nanoTime() < end) {
            String l = link.readLine(wait);
            if (l == null) {
                break;
            }
            got.add(l);
            wait = quietMillis;
        }
        return got;
    }

    /**
     * Lines that were neither a reply nor an error reply: a boot banner (the robot was reset and has
     * forgotten its speeds) or noise. A caller that keeps state on the robot sends it again when this grows.
     *
     * @return how many such lines were skipped while waiting for replies
     */
    public long foreignLines() {
        return foreignLines.sum();
    }

    /**
     * Boot banners seen in the middle of the session: the robot was reset (power dip, reset button,
     * a flat battery) and has forgotten its speeds and restarted its position counters at 0.
     *
     * @return how many banner lines arrived after {@link #open()}
     */
    public long boots() {
        return boots.sum();
    }


    private static boolean looksLikeReply(String line) {
        return line.equals(KheperaProtocol.COMMAND_NOT_FOUND)
                || (!line.isEmpty() && line.charAt(0) >= 'a' && line.charAt(0) <= 'z'
                        && (line.length() == 1 || line.charAt(1) == ','));
    }

    /** @return the last line written to the link, or null */
    public String lastSent() {
        return lastSent;
    }

    /** @return true once the link has gone */
    public boolean isLost() {
        return lost;
    }

    private SessionException lost(Command command, IOException e) {
        if (e instanceof LinkClosedException) {
            lost = true;
        }
        return new SessionException(SessionException.Kind.LINK_LOST, command, "lost the link while sending '"
                + command.encode() + "': " + e.getMessage(), e);
    }

    private void record(long rtt) {
        exchanges.increment();
        rttSum += rtt;
        rttMax = Math.max(rttMax, rtt);
    }

    private void countReply(String command, String reply) {
        int letter = command.isEmpty() ? -1 : Character.toUpperCase(command.charAt(0)) - 'A';
        if (letter >= 0 && letter < 26) {
            repliedChars[letter] += reply.length() + 2L; // the line and its CR LF
            replies[letter]++;
        }
    }

    /**
     * @param letter a command's letter, such as {@code 'N'}
     * @return {replies received, their characters with each line's CR LF}: what the robot's answers
     *     to that command have cost on the wire so far
     */
    public synchronized long[] replies(char letter) {
        int i = Character.toUpperCase(letter) - 'A';
        return i < 0 || i >= 26 ? new long[2] : new long[] {replies[i], repliedChars[i]};
    }

    /** @return counts and round-trip times so far */
    public synchronized Stats stats() {
        long n = exchanges.sum();
        return new Stats(n, retries.sum(), skippedLines.sum(), discardedChars.sum(), n == 0 ? 0 : rttSum / n, rttMax);
    }

    @Override
    public void close() {
        link.close();
    }
}
