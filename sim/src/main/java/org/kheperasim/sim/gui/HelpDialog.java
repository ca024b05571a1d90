package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Frame;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JDialog;
import javax.swing.JEditorPane;
import javax.swing.JList;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.ListSelectionModel;

/** The manual inside the window: the {@code docs/} pages, copied into the jar under {@code help/}. */
final class HelpDialog {
    private static final System.Logger LOG = System.getLogger(HelpDialog.class.getName());

    /** Every page of docs/, in reading order (a test checks that none is missing). */
    static final List<String> PAGES =
            List.of("quick-start.md", "gui.md", "arena-format.md", "robot-files.md", "simulation-model.md",
            "controller-rules.md", "swarms.md", "robot-link.md", "protocol-server.md", "wsu-migration.md", "grading.md",
            "testing.md", "autograding.md", "web-replay.md", "evaluate.md", "calibration.md",
            "adding-a-device.md", "startup.md", "faq.md");

    private HelpDialog() {
    }

    /** @param page a page's file name @return its text, or null if the jar does not have it */
    static String text(String page) {
        try (InputStream in = HelpDialog.class.getClassLoader().getResourceAsStream("help/" + page)) {
            return in == null ? null : new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            LOG.log(System.Logger.Level.WARNING, "cannot read the help page " + page + " from the jar: " + e);
            return null;
        }
    }

    /**
     * A page of the manual as the list shows it: by its title, not its file name.
     *
     * @param file its file name in docs/, e.g. {@code gui.md}
     * @param title its first heading, without Markdown's code marks
     */
    record Page(String file, String title) {
        @Override
        public String toString() {
            return title;
        }
    }

    /** @param file a page's file name @return the page, titled by its first heading (its file name if it has none) */
    static Page page(String file) {
        String text = text(file);
        String first = text == null ? "" : text.lines().filter(l -> l.startsWith("# ")).findFirst().orElse("");
        String title = first.isEmpty() ? file : first.substring(2).replace("`", "").strip();
        return new Page(file, title);
    }

    /** @return the dialog that shows the manual, open at {@code page} */
    static JDialog show(Frame owner, String page) {
        JDialog d = new JDialog(owner, "Khepera simulator - help", false);
        d.setName("help");
        List<Page> available = new ArrayList<>();
        for (String p : PAGES) {
            if (text(p) != null) {
                available.add(page(p));
            }
        }
        JList<Page> list = new JList<>(available.toArray(new Page[0]));
        list.setName("help.pages");
        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        // Esc closes it, as it closes any dialog.
        d.getRootPane().registerKeyboardAction(e -> d.dispose(), javax.swing.KeyStroke.getKeyStroke(
                java.awt.event.KeyEvent.VK_ESCAPE, 0), javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW);
        d.setDefaultCloseOperation(javax.swing.WindowConstants.DISPOSE_ON_CLOSE);
        JEditorPane view = new JEditorPane("text/html", "");
        view.setEditable(false);
        // A link to another page of the manual opens it here; any other goes to the browser.
        view.addHyperlinkListener(e -> {
            if (e.getEventType() != javax.swing.event.HyperlinkEvent.EventType.ACTIVATED) {
                return;
            }
            String href = String.valueOf(e.getDescription());
            String target = href.contains("#") ? href.substring(0, href.indexOf('#')) : href;
            Page linked = available.stream().filter(p -> p.file().equals(target)).findFirst().orElse(null);
            if (linked != null) {
                list.setSelectedValue(linked, true);
            } else if (e.getURL() != null && java.awt.Desktop.isDesktopSupported()) {
                try {
                    java.awt.Desktop.getDesktop().browse(e.getURL().toURI());
                } catch (IOException | java.net.URISyntaxException | UnsupportedOperationException ex) {
                    LOG.log(System.Logger.Level.INFO, "cannot open " + href + ": " + ex);
                }
            }
        });
        list.addListSelectionListener(e -> {
            Page sel = list.getSelectedValue();
            if (sel != null) {
                view.setText(Markdown.toHtml(text(sel.file())));
                view.setCaretPosition(0);
            }
        });
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, new JScrollPane(list), new JScrollPane(view));
        split.setDividerLocation(260);
        d.getContentPane().add(split, BorderLayout.CENTER);
        d.setBounds(WindowSize.fit(900, 700));
        if (available.isEmpty()) {
            view.setText("<html>The manual is not inside this build; read docs/ in the repository.</html>");
        } else {
            list.setSelectedValue(
                    available.stream().filter(p -> p.file().equals(page)).findFirst().orElse(available.get(0)), true);
        }
        d.setVisible(true);
        return d;
    }
}
