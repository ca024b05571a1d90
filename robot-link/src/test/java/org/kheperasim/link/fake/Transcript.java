package org.kheperasim.link.fake;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.link.io.Link;

/**
 * A recorded conversation with a robot in one dialect, from its manual or firmware: every command
 * and the reply it gets (test resources {@code transcripts/NAME.txt}, each naming its sources).
 * {@link #replay} sends each command over a link and checks each reply line.
 *
 * <p>Format, one item a line: {@code #} a comment; {@code > LINE} a command sent; {@code < PATTERN}
 * the next reply line, its comma-separated fields literal except {@code #}, which stands for any
 * integer (the manual's example values are the robot's, not these); {@code <~ TEXT} a reply line
 * that contains TEXT, lines before it skipped (help text, banners). After a {@code <~}, what else
 * the robot sends is let go before the next command.
 *
 * @param name the transcript's name (its dialect)
 * @param exchanges the commands and their expected replies, in order
 */
public record Transcript(String name, List<Exchange> exchanges) {

    /** @param command the line sent @param replies what the reply lines must be */
    public record Exchange(String command, List<String> replies) {
    }

    /**
     * @param name a transcript of the test resources, e.g. {@code epuck}
     * @return it, read
     */
    public static Transcript load(String name) throws IOException {
        try (InputStream in = Transcript.class.getResourceAsStream("/transcripts/" + name + ".txt")) {
            if (in == null) {
                throw new IOException("no transcript transcripts/" + name + ".txt on the test classpath");
            }
            List<Exchange> list = new ArrayList<>();
            for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
                String l = line.strip();
                if (l.isEmpty() || l.startsWith("#")) {
                    continue;
                }
                if (l.startsWith("> ")) {
                    list.add(new Exchange(l.substring(2), new ArrayList<>()));
                } else if (l.startsWith("<") && !list.isEmpty()) {
                    list.get(list.size() - 1).replies().add(l);
                } else {
                    throw new IOException("transcript " + name + ": line '" + l + "' is neither '> command' nor '< reply'");
                }
            }
            return new Transcript(name, list);
        }
    }

    /**
     * Send every command and check every reply.
     *
     * @param link an open link to the robot (or the simulator), its banner already read or not
     * @param timeoutMillis how long to wait for each reply line
     * @return how many reply lines were checked
     * @throws AssertionError naming the command, the expected and the received line
     */
    public int replay(Link link, long timeoutMillis) throws IOException {
        drain(link, 300);
        int checked = 0;
        for (Exchange e : exchanges) {
            link.discardInput();
            link.writeLine(e.command());
            boolean loose = false;
            for (String expected : e.replies()) {
                if (expected.startsWith("<~")) {
                    String text = expected.substring(2).strip();
                    loose = true;
                    String got;
                    do {
                        got = link.readLine(timeoutMillis);
                        if (got == null) {
                            throw new AssertionError(name + ": '" + e.command() + "' got no line containing '" + text + "'");
                        }
                    } while (!got.contains(text));
                } else {
                    String pattern = expected.substring(1).strip();
                    String got = link.readLine(timeoutMillis);
                    if (got == null || !matches(pattern, got)) {
                        throw new AssertionError(name + ": '" + e.command() + "' should get '" + pattern + "', got '"
                                + got + "'");
                    }
                }
                checked++;
            }
            if (loose) {
                drain(link, 200);
            }
        }
        return checked;
    }

    /** Read and drop lines until {@code quietMillis} pass without one. */
    private static void drain(Link link, long quietMillis) throws IOException {
        while (link.readLine(quietMillis) != null) {
            // a banner, the rest of a help text
        }
    }

    /**
     * @param pattern comma-separated fields, {@code #} for any integer
     * @param line a reply line
     * @return whether the line fits the pattern
     */
    public static boolean matches(String pattern, String line) {
        String[] p = pattern.split(",", -1);
        String[] l = line.split(",", -1);
        if (p.length != l.length) {
            return false;
        }
        for (int i = 0; i < p.length; i++) {
            if (p[i].equals("#") ? !l[i].matches("-?[0-9]+") : !p[i].equals(l[i])) {
                return false;
            }
        }
        return true;
    }
}
