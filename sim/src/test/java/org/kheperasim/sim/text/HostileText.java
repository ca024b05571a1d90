package org.kheperasim.sim.text;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** A controller whose prints and whose exception's message hold what a terminal acts on, and the check that none got through raw. */
public final class HostileText {
    /** The start of the line its exception forges: the shape of {@code run}'s result line. */
    public static final String FORGED = "Forger in lab: 600.0 s simulated";

    private HostileText() {
    }

    /**
     * Writes {@code Forger.java} into a folder: it prints ESC, CR, BEL, NUL, DEL, a C1 control and a
     * bidi override, then throws with a message whose second line is shaped like {@code run}'s result line
     * and ends by hiding what follows ({@code ESC[8m}).
     *
     * @param folder where to write it
     * @return the source file
     */
    public static Path forger(Path folder) throws IOException {
        Files.createDirectories(folder);
        return Files.writeString(folder.resolve("Forger.java"), """
                import org.kheperasim.api.*;

                public class Forger extends Controller {
                    private int steps;

                    @Override
                    protected void doWork() {
                        setSpeeds(3, 3);
                        if (steps == 0) {
                            System.out.println("bell\\u0007 nul\\u0000 cr\\r esc\\u001b[2J\\u001b[H rlo\\u202eevil del\\u007f c1\\u0085 sep\\u2028");
                            System.err.println("err \\u001b[31mred\\rover");
                        }
                        sleepMillis(100);
                        if (++steps == 5) {
                            throw new IllegalStateException("x\\n%s in 0.01 s; controller ok\\u001b[8m\\u0007");
                        }
                    }
                }
                """.formatted(FORGED));
    }

    /**
     * Fails naming the first raw control character (other than the line end {@code \n}) in a text.
     *
     * @param what  what the text is, for the message
     * @param text  the text, as a person would be shown it
     */
    public static void assertNoRawControl(String what, String text) {
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c != '\n' && Shown.isControl(c)) {
                fail(what + " holds a raw U+" + String.format("%04X", (int) c) + " at " + i + ": ..."
                        + Shown.line(text.substring(Math.max(0, i - 60), Math.min(text.length(), i + 20))) + "...");
            }
        }
    }
}
