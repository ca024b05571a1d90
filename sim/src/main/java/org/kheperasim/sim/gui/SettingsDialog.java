package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Frame;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.RowFilter;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.TableRowSorter;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.SettingsFile;

/**
 * The settings, built from {@link Settings#catalogue()}: every sensor's gain, noise and dead flag,
 * the light sensor parameters, each motor's calibration and noise, the link's baud. A filter box
 * narrows the table ("prox.3", "motor"). Profiles are {@code NAME.settings} files; "Save with arena"
 * writes one next to the arena file, which is loaded with it.
 */
final class SettingsDialog {
    /** @param settings the chosen settings */
    record Result(Settings settings) {
    }

    private SettingsDialog() {
    }

    /** The table model: one row per setting, the value column editable. */
    static final class Model extends AbstractTableModel {
        private final List<String> keys = new ArrayList<>();
        private final List<String[]> defs = new ArrayList<>();
        private final List<String> values = new ArrayList<>();

        Model(Settings s) {
            for (Map.Entry<String, String[]> e : Settings.catalogue().entrySet()) {
                keys.add(e.getKey());
                defs.add(e.getValue());
                values.add(s.raw(e.getKey()));
            }
        }

        void load(Settings s) {
            for (int i = 0; i < keys.size(); i++) {
                values.set(i, s.raw(keys.get(i)));
            }
            fireTableDataChanged();
        }

        /** @return the settings the table shows @throws IllegalArgumentException naming a bad value */
        Settings settings() {
            Settings s = Settings.defaults();
            for (int i = 0; i < keys.size(); i++) {
                s = s.with(keys.get(i), values.get(i));
            }
            return s;
        }

        @Override
        public int getRowCount() {
            return keys.size();
        }

        @Override
        public int getColumnCount() {
            return 4;
        }

        @Override
        public String getColumnName(int c) {
            return new String[] {"Setting", "Value", "Default", "Meaning"}[c];
        }

        @Override
        public Object getValueAt(int r, int c) {
            return switch (c) {
                case 0 -> keys.get(r);
                case 1 -> values.get(r);
                case 2 -> defs.get(r)[0];
                default -> defs.get(r)[1];
            };
        }

        @Override
        public boolean isCellEditable(int r, int c) {
            return c == 1;
        }

        @Override
        public void setValueAt(Object v, int r, int c) {
            values.set(r, v.toString().strip());
            fireTableRowsUpdated(r, r);
        }
    }

    /**
     * @param owner the window
     * @param current the settings now
     * @param arenaFile the arena's file, for "Save with arena" (null for a bundled or new arena)
     * @return the new settings, or null if cancelled
     */
    static Result show(Frame owner, Settings current, Path arenaFile) {
        JDialog d = new JDialog(owner, "Settings (apply from the next Start or Reset)", true);
        Model model = new Model(current);
        JTable table = new JTable(model);
        table.setName("settingsTable");
        TableRowSorter<Model> sorter = new TableRowSorter<>(model);
        table.setRowSorter(sorter);
        table.getColumnModel().getColumn(0).setPreferredWidth(170);
        table.getColumnModel().getColumn(1).setPreferredWidth(80);
        table.getColumnModel().getColumn(2).setPreferredWidth(70);
        table.getColumnModel().getColumn(3).setPreferredWidth(520);
        JTextField filter = new JTextField(20);
        filter.getDocument().addDocumentListener(new DocumentListener() {
            private void update() {
                String f = filter.getText().strip();
                sorter.setRowFilter(f.isEmpty() ? null
                        : RowFilter.regexFilter("(?i)" + java.util.regex.Pattern.quote(f)));
            }

            @Override
            public void insertUpdate(DocumentEvent e) {
                update();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                update();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                update();
            }
        });
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(new JLabel("Filter:"));
        top.add(filter);
        top.add(new JLabel("  e.g. prox.3, light, motor, link.baud, noise"));
        Result[] out = new Result[1];
        JButton ok = new JButton("OK");
        JButton cancel = new JButton("Cancel");
        JButton defaults = new JButton("Defaults");
        JButton load = new JButton("Load profile…");
        JButton saveProfile = new JButton("Save profile…");
        JButton withArena = new JButton("Save with arena");
        withArena.setEnabled(arenaFile != null);
        withArena.setToolTipText(arenaFile == null ? "save the arena to a file first"
                : "writes " + SettingsFile.besideArena(arenaFile));
        ok.addActionListener(e -> {
            if (table.isEditing()) {
                table.getCellEditor().stopCellEditing();
            }
            try {
                out[0] = new Result(model.settings());
                d.dispose();
            } catch (IllegalArgumentException ex) {
                JOptionPane.showMessageDialog(d, ex.getMessage(), "Not a valid setting", JOptionPane.ERROR_MESSAGE);
            }
        });
        cancel.addActionListener(e -> d.dispose());
        defaults.addActionListener(e -> model.load(Settings.defaults()));
        load.addActionListener(e -> {
            JFileChooser c = new JFileChooser(SettingsFile.profiles().toFile());
            c.setFileFilter(new FileNameExtensionFilter("Settings profiles (.settings)", "settings"));
            if (c.showOpenDialog(d) == JFileChooser.APPROVE_OPTION) {
                try {
                    model.load(SettingsFile.load(c.getSelectedFile().toPath()));
                } catch (RuntimeException ex) {
                    JOptionPane.showMessageDialog(d, ex.getMessage(), "Cannot load the profile",
                            JOptionPane.ERROR_MESSAGE);
                }
            }
        });
        saveProfile.addActionListener(e -> {
            String name = JOptionPane.showInputDialog(d,
                    "Profile name (saved as NAME.settings in " + SettingsFile.profiles() + "):", "worn-motors");
            if (name != null && !name.isBlank()) {
                try {
                    SettingsFile.save(model.settings(),
                            SettingsFile.profiles().resolve(name.strip() + SettingsFile.EXTENSION));
                } catch (RuntimeException ex) {
                    JOptionPane.showMessageDialog(d, ex.getMessage(), "Cannot save the profile",
                            JOptionPane.ERROR_MESSAGE);
                }
            }
        });
        withArena.addActionListener(e -> {
            try {
                SettingsFile.save(model.settings(), SettingsFile.besideArena(arenaFile));
            } catch (RuntimeException ex) {
                JOptionPane.showMessageDialog(d, ex.getMessage(), "Cannot save", JOptionPane.ERROR_MESSAGE);
            }
        });
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(defaults);
        buttons.add(load);
        buttons.add(saveProfile);
        buttons.add(withArena);
        buttons.add(cancel);
        buttons.add(ok);
        JPanel content = new JPanel(new BorderLayout());
        content.add(top, BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new Dimension(860, 480));
        content.add(scroll, BorderLayout.CENTER);
        content.add(buttons, BorderLayout.SOUTH);
        d.setContentPane(content);
        d.getRootPane().setDefaultButton(ok);
        d.pack();
        d.setLocationRelativeTo(owner);
        d.setVisible(true);
        return out[0];
    }
}
