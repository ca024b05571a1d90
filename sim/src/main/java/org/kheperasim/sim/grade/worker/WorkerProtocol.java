package org.kheperasim.sim.grade.worker;

import java.net.URLDecoder;
import java.net.URLEncoder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * What a grader and its warm worker JVM say to each other (docs/grading.md, "Warm workers").
 *
 * <p>The grader writes one request a line on the worker's standard input: {@code run INDEX TOKEN
 * ARG...}, the arguments of {@code run} as a graded child gets them (its arena, classes, seed,
 * limits and the run's own command-log socket), each URL-encoded. The end of standard input means
 * the grader is done or gone: the worker ends at once, mid-run or not.
 *
 * <p>The worker marks its standard error, where a graded child's error lines go, with lines that
 * start with {@link #MARK} and the run's token: {@code start INDEX} before the run, {@code done
 * INDEX EXIT} where a JVM of its own would have ended with that exit status, then {@code ready}
 * when it may take the next run, or {@code restart REASON} as it ends itself to be replaced. What
 * comes between a run's start and its done is that run's standard error. The token is the
 * grader's, fresh for each run and never shown to controller code, so a controller's output cannot
 * pass for a mark; even if it could, a worker only ever makes one submission's runs and says no more
 * about them than a child JVM's exit status and standard error did (the score is the grader's replay).
 */
public final class WorkerProtocol {
    /** The start of every mark on the worker's standard error. */
    public static final String MARK = "\u0001khepera-worker ";

    private WorkerProtocol() {
    }

    /**
     * A request for one run.
     *
     * @param index the run's index in the grading
     * @param token the grader's token for it (letters and digits)
     * @param args  the graded run's arguments
     */
    public record Request(int index, String token, List<String> args) {
        /** Copies the arguments. */
        public Request {
            args = List.copyOf(args);
            if (!token.matches("[A-Za-z0-9]+")) {
                throw new IllegalArgumentException("a worker token is letters and digits: " + token);
            }
        }

        /** @return the request as one line, without its end of line */
        public String line() {
            StringBuilder s = new StringBuilder("run ").append(index).append(' ').append(token);
            for (String a : args) {
                s.append(' ').append(URLEncoder.encode(a, StandardCharsets.UTF_8));
            }
            return s.toString();
        }

        /**
         * @param line a request line
         * @return the request
         * @throws IllegalArgumentException if it is not one
         */
        public static Request parse(String line) {
            String[] f = line.split(" ");
            if (f.length < 3 || !f[0].equals("run")) {
                throw new IllegalArgumentException("not a worker request: " + line);
            }
            List<String> args = new ArrayList<>();
            for (int i = 3; i < f.length; i++) {
                args.add(URLDecoder.decode(f[i], StandardCharsets.UTF_8));
            }
            try {
                return new Request(Integer.parseInt(f[1]), f[2], args);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("not a worker request: " + line, e);
            }
        }
    }

    /** What a mark says. */
    public enum Kind {
        /** The run starts: its standard error follows. */
        START,
        /** The run has ended with this exit status: its standard error is over. */
        DONE,
        /** The worker waits for the next request. */
        READY,
        /** The worker ends itself to be replaced, for the reason given. */
        RESTART
    }

    /**
     * A mark.
     *
     * @param kind  what it says
     * @param token the run's token
     * @param index the run (START, DONE), else -1
     * @param exit  the run's exit status (DONE), else 0
     * @param why   why the worker is to be replaced (RESTART), else empty
     */
    public record Mark(Kind kind, String token, int index, int exit, String why) {
        /** @return the mark as a line, without its end of line */
        public String line() {
            return MARK + token + " " + switch (kind) {
                case START -> "start " + index;
                case DONE -> "done " + index + " " + exit;
                case READY -> "ready";
                case RESTART -> "restart " + why.replaceAll("[\\r\\n]+", " ");
            };
        }

        /**
         * @param text  what follows {@link #MARK} on a line of the worker's standard error
         * @param token the token the grader expects
         * @return the mark, or null when it is not one with that token (then it is plain output)
         */
        public static Mark parse(String text, String token) {
            if (token == null || !text.startsWith(token + " ")) {
                return null;
            }
            String[] f = text.substring(token.length() + 1).split(" ", 2);
            String rest = f.length > 1 ? f[1] : "";
            try {
                return switch (f[0]) {
                    case "start" -> new Mark(Kind.START, token, Integer.parseInt(rest.strip()), 0, "");
                    case "done" -> {
                        String[] n = rest.strip().split(" ");
                        yield n.length == 2 ? new Mark(Kind.DONE, token, Integer.parseInt(n[0]),
                                Integer.parseInt(n[1]), "") : null;
                    }
                    case "ready" -> rest.isBlank() ? new Mark(Kind.READY, token, -1, 0, "") : null;
                    case "restart" -> new Mark(Kind.RESTART, token, -1, 0, rest.strip());
                    default -> null;
                };
            } catch (NumberFormatException e) {
                return null;
            }
        }
    }
}
