package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.FlowLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.kheperasim.sim.text.Shown;

/**
 * The status bar: a message, the mouse's position in the arena, and the clock: the shown source's
 * state, simulated time, real-time factor and frame rate. A message lasts until the next one; a
 * refusal or a failed command shows in red for 6 s and then gives way to the message it covered;
 * an alert (a controller that failed, a file that does not compile) stays red until the next
 * message. Every message is also the label's tool tip, so a long one can be read whole.
 */
final class StatusBar {
    private static final long ERROR_NANOS = 6_000_000_000L;
    private static final Color RED = new Color(0xC00000);

    private final JLabel message = new JLabel(" ");
    private final JLabel position = new JLabel(" ");
    private final JLabel clock = new JLabel(" ");
    private final JLabel score = new JLabel("");
    private final JPanel bar = new JPanel(new BorderLayout());
    private long messageUntil;
    private Runnable onExpire = () -> { };
    /** The message a passing error covers, and whether it is an alert. */
    private String lasting = " ";
    private boolean lastingRed;

    StatusBar() {
        bar.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        message.setName("message");
        clock.setName("clock");
        score.setName("score");
        // The message gives way to nothing: it takes the room the others leave, down to a little.
        message.setMinimumSize(new java.awt.Dimension(80, message.getPreferredSize().height));
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

    /**
     * @param text the message
     * @param error true for a refusal or a failed command: red for 6 s, then the message it covered comes back
     */
    void show(String text, boolean error) {
        if (error) {
            set(text, true);
            messageUntil = System.nanoTime() + ERROR_NANOS;
        } else {
            lasting = text;
            lastingRed = false;
            set(text, false);
            messageUntil = 0;
        }
    }

    /** @param text what went wrong, in red until the next message (a controller that failed, a compile error) */
    void alert(String text) {
        lasting = Shown.visible(text);   // it names a controller's failure: its message is the controller's text
        lastingRed = true;
        set(lasting, true);
        messageUntil = 0;
    }

    /** @return true while an alert is shown (a later state must not hide it) */
    boolean alerting() {
        return lastingRed;
    }

    private void set(String text, boolean red) {
        message.setText(text);
        message.setToolTipText(text.isBlank() ? null : text);
        message.setForeground(red ? RED : Color.DARK_GRAY);
    }

    /**
     * @param state the shown source's state, or null
     * @param seconds simulated time shown, s
     * @param rtf the real-time factor in words ("-" when not running)
     * @param fps frames per second painted
     * @param mouse the mouse's arena position, mm (NaN when outside)
     */
    void update(String state, double seconds, String rtf, double fps, double[] mouse) {
        clock.setText(String.format(Locale.ROOT, "  %s   t = %.2f s   %s   %.0f fps  ",
                state == null ? "no run" : state, seconds, "-".equals(rtf) ? "" : rtf + " real time", fps));
        clock.setToolTipText(
                "the run's state, its simulated time, simulated seconds per real second, frames drawn per second");
        position.setText(Double.isNaN(mouse[0]) ? "  "
                : String.format(Locale.ROOT, "  (%.1f, %.1f) mm  ", mouse[0], mouse[1]));
        if (messageUntil != 0 && System.nanoTime() > messageUntil) {
            set(lasting, lastingRed);
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

    /** @return true when the message shown is red (tests) */
    boolean messageRed() {
        return RED.equals(message.getForeground());
    }

    /** @return the score shown, e.g. {@code score 39.77/100}, or empty (tests) */
    String scoreShown() {
        return score.getText().strip();
    }
}
