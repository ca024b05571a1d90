package org.kheperasim.link.calibrate;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * The questions the procedure asks the person at the robot. Each question has a key; interactively
 * the person types the answer (an empty line takes the default shown), and with
 * {@code --non-interactive} every question takes the answer given for its key, or its default.
 */
public final class Answers {
    private final PrintWriter out;
    private final BufferedReader in;
    private final Map<String, String> given;
    private final Consumer<String> beforeAnswer;

    /**
     * @param out where the questions go
     * @param in the person's answers; null: non-interactive
     * @param given answers by key (non-interactive, and interactive defaults)
     * @param beforeAnswer told each question's key before it is answered (tests set the scene here)
     */
    public Answers(PrintWriter out, BufferedReader in, Map<String, String> given, Consumer<String> beforeAnswer) {
        this.out = out;
        this.in = in;
        this.given = Map.copyOf(given);
        this.beforeAnswer = beforeAnswer;
    }

    /**
     * @param key the question's key ({@code --answer KEY=VALUE})
     * @param prompt what the person must do or measure
     * @param dflt the answer an empty line (or a missing {@code --answer}) takes
     * @return the answer
     */
    public String ask(String key, String prompt, String dflt) {
        beforeAnswer.accept(key);
        String d = given.getOrDefault(key, dflt);
        out.print(prompt + (d.isEmpty() ? "" : " [" + d + "]") + " (" + key + "): ");
        String a;
        if (in == null) {
            a = d;
            out.println(a);
        } else {
            out.flush();
            try {
                String line = in.readLine();
                a = line == null || line.isBlank() ? d : line.trim();
            } catch (IOException e) {
                a = d;
            }
        }
        out.flush();
        return a;
    }

    /** As {@link #ask}, for a number: @return it */
    public double number(String key, String prompt, double dflt) {
        String a = ask(key, prompt, fmt(dflt));
        try {
            return Double.parseDouble(a);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("answer " + key + "=" + a + ": not a number; give it like 12.5");
        }
    }

    /** Says what the person must do, and waits for Enter (non-interactive: goes on). */
    public void pause(String key, String prompt) {
        ask(key, prompt + " then press Enter", "");
    }

    static String fmt(double v) {
        return String.format(Locale.ROOT, "%.6g", v).replaceAll("\\.?0+$", "").replaceAll("\\.?0+e", "e");
    }
}
