package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
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
    static final List<String> PAGES = List.of("quick-start.md", "gui.md", "arena-format.md", "simulation-model.md",
            "controller-rules.md", "swarms.md", "robot-link.md", "protocol-server.md", "wsu-migration.md", "grading.md",
            "testing.md", "autograding.md", "web-replay.md", "faq.md");

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

    static void show(Frame owner, String page) {
        JDialog d = new JDialog(owner, "Khepera simulator - help", false);
        List<String> available = new ArrayList<>();
        for (String p : PAGES) {
            if (text(p) != null) {
                available.add(p);
            }
        }
        JList<String> list = new JList<>(available.toArray(new String[0]));
        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        JEditorPane view = new JEditorPane("text/html", "");
        view.setEditable(false);
        // A link to another page of the manual opens it here; any other goes to the browser.
        view.addHyperlinkListener(e -> {
            if (e.getEventType() != javax.swing.event.HyperlinkEvent.EventType.ACTIVATED) {
                return;
            }
            String href = String.valueOf(e.getDescription());
            String target = href.contains("#") ? href.substring(0, href.indexOf('#')) : href;
            if (available.contains(target)) {
                list.setSelectedValue(target, true);
            } else if (e.getURL() != null && java.awt.Desktop.isDesktopSupported()) {
                try {
                    java.awt.Desktop.getDesktop().browse(e.getURL().toURI());
                } catch (IOException | java.net.URISyntaxException | UnsupportedOperationException ex) {
                    LOG.log(System.Logger.Level.INFO, "cannot open " + href + ": " + ex);
                }
            }
        });
        list.addListSelectionListener(e -> {
            String sel = list.getSelectedValue();
            if (sel != null) {
                view.setText(Markdown.toHtml(text(sel)));
                view.setCaretPosition(0);
            }
        });
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, new JScrollPane(list), new JScrollPane(view));
        split.setDividerLocation(170);
        d.getContentPane().add(split, BorderLayout.CENTER);
        d.setSize(new Dimension(900, 700));
        d.setLocationRelativeTo(owner);
        if (available.isEmpty()) {
            view.setText("<html>The manual is not inside this build; read docs/ in the repository.</html>");
        } else {
            list.setSelectedValue(available.contains(page) ? page : available.get(0), true);
        }
        d.setVisible(true);
    }
}
