package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Font;
import java.util.concurrent.ConcurrentLinkedQueue;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextPane;
import javax.swing.text.BadLocationException;
import javax.swing.text.SimpleAttributeSet;
import javax.swing.text.StyleConstants;
import javax.swing.text.StyledDocument;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ConsoleSink;

/**
 * The console: the controller's {@code MessagePasser} output, its errors (with the stack trace
 * down to the student's own line) and notes from the simulator. Lines arrive on the engine's and
 * controllers' threads; they are queued without waiting and shown by the window's timer.
 */
final class ConsolePanel extends JPanel implements ConsoleSink {
    private static final int MAX_CHARS = 200_000;
    /** The source of the window's own lines. */
    private static final String SIMULATOR = "simulator";
    private final ConcurrentLinkedQueue<ConsoleLine> pending = new ConcurrentLinkedQueue<>();
    private final JTextPane text = new JTextPane();
    private final SimpleAttributeSet normal = new SimpleAttributeSet();
    private final SimpleAttributeSet error = new SimpleAttributeSet();
    private final SimpleAttributeSet info = new SimpleAttributeSet();
    private volatile int errors;

    ConsolePanel() {
        super(new BorderLayout());
        setName("console");
        text.setEditable(false);
        text.setName("consoleText");
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        StyleConstants.setForeground(error, new Color(0xC00000));
        StyleConstants.setBold(error, true);
        StyleConstants.setForeground(info, new Color(0x555555));
        StyleConstants.setItalic(info, true);
        JButton clear = new JButton("Clear");
        clear.addActionListener(e -> text.setText(""));
        JPanel top = new JPanel(new BorderLayout());
        top.add(new javax.swing.JLabel(" Console: messages from the controller, errors, notes"), BorderLayout.CENTER);
        top.add(clear, BorderLayout.EAST);
        add(top, BorderLayout.NORTH);
        add(new JScrollPane(text), BorderLayout.CENTER);
    }

    @Override
    public void accept(ConsoleLine line) {
        if (line.kind() == ConsoleLine.Kind.ERROR) {
            errors++;
        }
        pending.add(line);
    }

    /** Where the window's own notes take their time stamp from: the run's simulated time now. */
    private volatile java.util.function.LongSupplier now = () -> 0;

    /** @param clock the simulated time now, ns (0 with no run) */
    void clock(java.util.function.LongSupplier clock) {
        now = clock;
    }

    /** @param text a note from the window itself, stamped with the run's simulated time */
    void note(String note) {
        pending.add(new ConsoleLine(now.getAsLong(), SIMULATOR, ConsoleLine.Kind.INFO, note));
    }

    /** @param text an error from the window itself (a compile error, say) */
    void error(String message) {
        errors++;
        pending.add(new ConsoleLine(now.getAsLong(), SIMULATOR, ConsoleLine.Kind.ERROR, message));
    }

    private java.util.function.Consumer<ConsoleLine> controllerErrors = l -> { };

    /** @param l told on the event thread of every error line a controller's run sends (not the window's own) */
    void onControllerError(java.util.function.Consumer<ConsoleLine> l) {
        controllerErrors = l;
    }

    /** @return errors shown so far */
    int errors() {
        return errors;
    }

    /** Show what has arrived (on the event thread). */
    void drain() {
        ConsoleLine line;
        StyledDocument doc = text.getStyledDocument();
        boolean any = false;
        try {
            while ((line = pending.poll()) != null) {
                SimpleAttributeSet style = switch (line.kind()) {
                    case ERROR -> error;
                    case INFO -> info;
                    case MESSAGE -> normal;
                };
                doc.insertString(doc.getLength(), line.format() + "\n", style);
                any = true;
                if (line.kind() == ConsoleLine.Kind.ERROR && !SIMULATOR.equals(line.source())) {
                    controllerErrors.accept(line);
                }
            }
            if (doc.getLength() > MAX_CHARS) {
                doc.remove(0, doc.getLength() - MAX_CHARS / 2);
            }
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        if (any) {
            text.setCaretPosition(doc.getLength());
        }
    }

    /** @return everything shown (for tests) */
    String contents() {
        return text.getText();
    }
}
