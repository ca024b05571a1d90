package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.FlowLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * The status bar: a message (refusals and errors in red, kept 6 s), the mouse's position in the
 * arena, and the clock: the shown source's state, simulated time, real-time factor and frame rate.
 */
final class StatusBar {
    private static final long ERROR_NANOS = 6_000_000_000L;

    private final JLabel message = new JLabel(" ");
    private final JLabel position = new JLabel(" ");
    private final JLabel clock = new JLabel(" ");
    private final JLabel score = new JLabel("");
    private final JPanel bar = new JPanel(new BorderLayout());
    private long messageUntil;
    private Runnable onExpire = () -> { };

    StatusBar() {
        bar.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        message.setName("message");
        clock.setName("clock");
        score.setName("score");
        bar.add(message, BorderLayout.CENTER);
        JPanel east = new JPanel(new FlowLayout(FlowLayout.RIGHT, 0, 0));
        east.add(score);
        east.add(position);
        east.add(clock);
        bar.add(east, BorderLayout.EAST);
    }

    /** @return the bar */
    JComponent component() {
        return bar;
    }

    /** @param r what to do when an error message expires */
    void onExpire(Runnable r) {
        onExpire = r;
    }

    /** @param text the message @param error shown in red for 6 s when true */
    void show(String text, boolean error) {
        message.setText(text);
        message.setForeground(error ? new Color(0xC00000) : Color.DARK_GRAY);
        messageUntil = error ? System.nanoTime() + ERROR_NANOS : 0;
    }

    /**
     * @param state the shown source's state, or null
     * @param seconds simulated time shown, s
     * @param rtf the real-time factor in words ("-" when not running)
     * @param fps frames per second painted
     * @param mouse the mouse's arena position, mm (NaN when outside)
     */
    void update(String state, double seconds, String rtf, double fps, double[] mouse) {
        clock.setText(String.format(Locale.ROOT, "  %s   t = %.2f s   real-time factor %s   %.0f fps  ",
                state == null ? "no run" : state, seconds, rtf, fps));
        position.setText(Double.isNaN(mouse[0]) ? "  " : String.format(Locale.ROOT, "  (%.1f, %.1f) mm  ", mouse[0], mouse[1]));
        if (messageUntil != 0 && System.nanoTime() > messageUntil) {
            message.setText(" ");
            messageUntil = 0;
            onExpire.run();
        }
    }

    /** @param text the assignment's score in words, or null to show none */
    void score(String text) {
        String t = text == null ? "" : "  " + text.replaceFirst(" \\(.*", "") + "  ";
        if (!t.equals(score.getText())) {
            score.setText(t);
            score.setToolTipText(text);
        }
    }

    /** @return the message shown (tests) */
    String message() {
        return message.getText();
    }
}
