package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import org.kheperasim.sim.replay.Replay;

/**
 * The recorder's controls under the arena while a replay is open: rewind, step back, play/pause,
 * step, fast-forward, speed, a timeline to scrub, the time, and Close.
 */
final class ReplayBar {
    /** Timeline resolution: slider positions over the run. */
    static final int TICKS = 10_000;

    private final ReplayPlayer player;
    private final JPanel panel = new JPanel(new BorderLayout(6, 0));
    private final JSlider timeline = new JSlider(0, TICKS, 0);
    private final JLabel time = new JLabel(" ");
    private final JButton play = new JButton("Play");
    private final JComboBox<String> speedBox = new JComboBox<>();
    private boolean updating;

    /** @param close what Close does */
    ReplayBar(ReplayPlayer player, Runnable close) {
        this.player = player;
        panel.setName("replayBar");
        panel.setBorder(BorderFactory.createEmptyBorder(2, 4, 2, 4));
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 2, 0));
        buttons.add(button("replay.rewind", "|<<", "back to the start", player::rewind));
        buttons.add(button("replay.back", "<|", "one sample back", () -> player.step(-1)));
        play.setName("replay.play");
        play.setToolTipText("play or pause (Space)");
        play.setFocusable(false);
        play.addActionListener(e -> player.toggle());
        buttons.add(play);
        buttons.add(button("replay.step", "|>", "one sample on", () -> player.step(1)));
        buttons.add(button("replay.forward", ">>", "fast-forward: play at the next faster speed", player::fastForward));
        for (double s : ReplayPlayer.SPEEDS) {
            speedBox.addItem("x" + (s == StrictMath.rint(s) ? Integer.toString((int) s) : Double.toString(s)));
        }
        speedBox.setName("replay.speed");
        speedBox.setFocusable(false);
        speedBox.setSelectedIndex(2);
        speedBox.addActionListener(e -> {
            if (!updating) {
                player.setSpeed(ReplayPlayer.SPEEDS[speedBox.getSelectedIndex()]);
            }
        });
        buttons.add(speedBox);
        timeline.setName("replay.timeline");
        timeline.setFocusable(false);
        timeline.addChangeListener(e -> {
            Replay r = player.replay();
            if (!updating && r != null) {
                player.pause();
                player.seek(r.startSeconds() + (r.endSeconds() - r.startSeconds()) * timeline.getValue() / TICKS);
            }
        });
        time.setName("replay.time");
        JPanel east = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        east.add(time);
        east.add(button("replay.close", "Close replay", "back to editing and running", close));
        // The timeline gets the whole width: the finer the scrubbing, the better.
        JPanel controls = new JPanel(new BorderLayout());
        controls.add(buttons, BorderLayout.WEST);
        controls.add(east, BorderLayout.EAST);
        panel.add(timeline, BorderLayout.NORTH);
        panel.add(controls, BorderLayout.SOUTH);
        panel.setVisible(false);
    }

    private static JButton button(String name, String label, String tip, Runnable body) {
        JButton b = new JButton(label);
        b.setName(name);
        b.setToolTipText(tip);
        b.setFocusable(false);
        b.addActionListener(e -> body.run());
        return b;
    }

    /** @return the bar */
    JComponent component() {
        return panel;
    }

    /** Show the player's state (each frame). */
    void update() {
        Replay r = player.replay();
        panel.setVisible(r != null);
        if (r == null) {
            return;
        }
        updating = true;
        try {
            double span = r.endSeconds() - r.startSeconds();
            if (!timeline.getValueIsAdjusting()) { // never fight the user's drag
                timeline.setValue(span <= 0 ? 0
                        : (int) StrictMath.round((player.cursor() - r.startSeconds()) / span * TICKS));
            }
            play.setText(player.playing() ? "Pause" : "Play");
            for (int i = 0; i < ReplayPlayer.SPEEDS.length; i++) {
                if (ReplayPlayer.SPEEDS[i] == player.speed() && speedBox.getSelectedIndex() != i) {
                    speedBox.setSelectedIndex(i);
                }
            }
            time.setText(String.format(Locale.ROOT, "%.2f / %.2f s", player.cursor(), r.endSeconds()));
        } finally {
            updating = false;
        }
    }
}
