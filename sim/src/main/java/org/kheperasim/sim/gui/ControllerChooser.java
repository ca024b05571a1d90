package org.kheperasim.sim.gui;

import java.awt.Dimension;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.DefaultComboBoxModel;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.ControllerCompiler;

/**
 * Which controller the next run uses: the toolbar's box of bundled ones, compiled classes from a
 * folder or jar, a {@code .java} the window compiles (errors with line numbers in the console),
 * Reload (F10), and per-robot controllers.
 */
final class ControllerChooser {
    private static final System.Logger LOG = System.getLogger(ControllerChooser.class.getName());

    private final JFrame frame;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunChoices choices;
    private final RobotControllers robotControllers;
    private final RobotSelection selection;
    private final Runnable discardRun;
    private final JFileChooser chooser = new JFileChooser(new File("."));
    private final JComboBox<String> box = new JComboBox<>();

    ControllerChooser(JFrame frame, ConsolePanel console, StatusBar status, RunChoices choices,
            RobotControllers robotControllers, RobotSelection selection, Runnable discardRun) {
        this.frame = frame;
        this.console = console;
        this.status = status;
        this.choices = choices;
        this.robotControllers = robotControllers;
        this.selection = selection;
        this.discardRun = discardRun;
        for (String c : ControllerCatalog.bundled()) {
            box.addItem(c);
        }
        offer(choices.controllerName);
        box.setSelectedItem(choices.controllerName);
        box.setName("controller");
        box.setMaximumSize(new Dimension(160, box.getPreferredSize().height));
        box.addActionListener(e -> {
            Object sel = box.getSelectedItem();
            if (sel != null && !sel.equals(choices.controllerName)) {
                choices.controllerName = sel.toString();
                discardRun.run();
                console.note("Controller " + choices.controllerName + " chosen; press Start.");
            }
        });
    }

    /** @return the toolbar's box */
    JComboBox<String> box() {
        return box;
    }

    /** @return true when Reload has something to do */
    boolean canReload() {
        return choices.javaSource != null || !choices.classpath.isEmpty();
    }

    private void offer(String name) {
        if (((DefaultComboBoxModel<String>) box.getModel()).getIndexOf(name) < 0) {
            box.addItem(name);
        }
    }

    void loadClasses() {
        chooser.setFileSelectionMode(JFileChooser.FILES_AND_DIRECTORIES);
        chooser.setDialogTitle("A folder with your .class files, or a jar");
        if (chooser.showOpenDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path p = chooser.getSelectedFile().toPath();
        String name = JOptionPane.showInputDialog(frame, "The controller's class name (with its package, if any):", guessClass(p));
        if (name == null || name.isBlank()) {
            return;
        }
        use(List.of(p), name.strip(), null);
    }

    private static String guessClass(Path p) {
        if (!Files.isDirectory(p)) {
            return "Robot";
        }
        try (var files = Files.walk(p, 4)) {
            return files.filter(f -> f.toString().endsWith(".class") && !f.getFileName().toString().contains("$"))
                    .map(f -> p.relativize(f).toString().replace(File.separatorChar, '.').replaceFirst("\\.class$", ""))
                    .findFirst().orElse("Robot");
        } catch (IOException e) {
            LOG.log(System.Logger.Level.DEBUG, "cannot look for classes in " + p + ", guessing Robot: " + e);
            return "Robot";
        }
    }

    private void use(List<Path> cp, String name, Path source) {
        try {
            new ControllerCatalog(cp).load(name);
        } catch (RuntimeException e) {
            console.error(e.getMessage());
            status.show("Cannot use " + name + ": " + e.getMessage(), true);
            return;
        }
        choices.classpath = new ArrayList<>(cp);
        choices.javaSource = source;
        choices.controllerName = name;
        discardRun.run();
        offer(name);
        box.setSelectedItem(name);
        console.note("Controller " + name + " loaded from " + cp + ". Press Start.");
        status.show("Controller " + name + " loaded. Press Start.", false);
    }

    void openJava() {
        chooser.setFileSelectionMode(JFileChooser.FILES_ONLY);
        chooser.setDialogTitle("A controller's .java source");
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            compileAndUse(chooser.getSelectedFile().toPath());
        }
    }

    /** @param source compile it and make it the controller @return true if it compiled */
    boolean compileAndUse(Path source) {
        ControllerCompiler.Result result;
        try {
            Path out = Path.of(System.getProperty("user.home"), ".khepera-sim", "classes",
                    source.getFileName().toString().replaceFirst("\\.java$", "") + "-" + Long.toHexString(System.nanoTime()));
            result = ControllerCompiler.compile(source, out);
        } catch (IOException | RuntimeException e) {
            console.error("cannot compile " + source + ": " + e.getMessage());
            status.show("Cannot compile: " + e.getMessage(), true);
            return false;
        }
        if (!result.success()) {
            console.error("compiling " + source.getFileName() + " failed:\n" + result.report(source.toString()));
            status.show("Compile errors in " + source.getFileName() + ": see the console (line numbers given)", true);
            choices.javaSource = source;
            return false;
        }
        if (!result.problems().isEmpty()) {
            console.note(result.report(source.toString()));
        }
        console.note("Compiled " + source.getFileName() + " into " + result.classes());
        use(List.of(result.classes()), result.className(), source);
        return true;
    }

    /** Recompile the .java (if one was opened) or read the class afresh at the next Start. */
    void reload() {
        if (choices.javaSource != null) {
            compileAndUse(choices.javaSource);
        } else {
            discardRun.run();
            console.note("Reloaded: the controller class is read afresh at Start.");
        }
    }

    /** The selected robot runs the chosen controller from the next Start. */
    void assignSelected() {
        int i = selection.index();
        robotControllers.assign(i, choices.controllerName);
        console.note("robot " + i + " will run " + choices.controllerName + " from the next Start");
    }

    /** Every robot runs the chosen controller from the next Start. */
    void clearAssignments() {
        robotControllers.clear();
        console.note("every robot will run the controller chosen in the box from the next Start");
    }
}
