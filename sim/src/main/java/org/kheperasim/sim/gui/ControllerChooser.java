package org.kheperasim.sim.gui;

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
        // As wide as the bundled names need and no wider: a long class name is cut short in the box
        // (its tool tip has it whole), where it pushed the box off the toolbar.
        box.setPrototypeDisplayValue("StepBraitenberg   ");
        // A class in a package shows by its simple name (its full name is in the list's tool tip and the title).
        box.setRenderer(new javax.swing.DefaultListCellRenderer() {
            @Override
            public java.awt.Component getListCellRendererComponent(javax.swing.JList<?> list, Object value, int index,
                    boolean selected, boolean focus) {
                String full = String.valueOf(value);
                super.getListCellRendererComponent(list, full.substring(full.lastIndexOf('.') + 1), index,
                        selected, focus);
                setToolTipText(full);
                return this;
            }
        });
        box.setToolTipText("the controller the next run uses: " + choices.controllerName);
        box.addActionListener(e -> {
            Object sel = box.getSelectedItem();
            box.setToolTipText(sel == null ? null : "the controller the next run uses: " + sel);
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
        chooser.resetChoosableFileFilters();
        chooser.setFileSelectionMode(JFileChooser.FILES_AND_DIRECTORIES);
        chooser.setDialogTitle("A folder with your .class files, or a jar");
        if (chooser.showOpenDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path p = chooser.getSelectedFile().toPath();
        String name = JOptionPane.showInputDialog(frame,
                "The controller's class name (with its package, if any):", guessClass(p));
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
        if (source == null) {
            choices.sourceClass = null;
            choices.compiledText = null;
            choices.failedText = null;
        }
        choices.controllerName = name;
        discardRun.run();
        offer(name);
        box.setSelectedItem(name);
        console.note("Controller " + name + " loaded from " + cp + ". Press Start.");
        status.show("Controller " + name + " loaded. Press Start.", false);
    }

    void openJava() {
        chooser.resetChoosableFileFilters();
        chooser.setFileSelectionMode(JFileChooser.FILES_ONLY);
        chooser.setDialogTitle("A controller's .java source");
        javax.swing.filechooser.FileNameExtensionFilter java = new javax.swing.filechooser.FileNameExtensionFilter(
                "Java sources (.java)", "java");
        chooser.addChoosableFileFilter(java);
        chooser.setFileFilter(java);
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            compileAndUse(chooser.getSelectedFile().toPath());
        }
    }

    /**
     * Compile a {@code .java} and make its class the controller. When it does not compile, its class
     * is still the chosen controller, and Start refuses to run until it compiles: never the last
     * version that compiled, which a student would take for the file they see.
     *
     * @param source compile it and make it the controller
     * @return true if it compiled
     */
    boolean compileAndUse(Path source) {
        ControllerCompiler.Result result;
        String text;
        try {
            text = Files.readString(source);
            Path out = Path.of(System.getProperty("user.home"), ".khepera-sim", "classes",
                    source.getFileName().toString().replaceFirst("\\.java$", "") + "-"
                            + Long.toHexString(System.nanoTime()));
            result = ControllerCompiler.compile(source, out);
        } catch (IOException | RuntimeException e) {
            console.error("cannot compile " + source + ": " + e.getMessage());
            status.alert("Cannot compile " + source.getFileName() + ": " + e.getMessage());
            return false;
        }
        if (!result.success()) {
            String report = result.report(source.toString());
            console.error("compiling " + source.getFileName() + " failed:\n" + report);
            choices.javaSource = source;
            choices.sourceClass = result.className();
            choices.failedText = text;
            choices.failedError =
                    report.lines().findFirst().orElse("").replace(source.toString(), source.getFileName().toString());
            choices.controllerName = result.className();
            discardRun.run();
            offer(result.className());
            box.setSelectedItem(result.className());
            status.alert(source.getFileName() + " does not compile: " + choices.failedError
                    + ". Fix it, then Start (F5) or"
                    + " Reload (F10) compiles it again; until then nothing runs");
            return false;
        }
        if (!result.problems().isEmpty()) {
            console.note(result.report(source.toString()));
        }
        console.note("Compiled " + source.getFileName() + " into " + result.classes());
        use(List.of(result.classes()), result.className(), source);
        choices.sourceClass = result.className();
        choices.compiledText = text;
        choices.failedText = null;
        choices.failedError = null;
        return true;
    }

    /**
     * Before a new run of a controller opened as a {@code .java}: a file changed since it was
     * compiled is compiled again (the run is the file as it is now), and a file that does not
     * compile stops the run, saying where, rather than run the last version that did.
     *
     * @return true when the run may start
     */
    boolean readyForNewRun() {
        Path source = choices.javaSource;
        if (source == null || !choices.controllerName.equals(choices.sourceClass)) {
            return true;
        }
        String now;
        try {
            now = Files.readString(source);
        } catch (IOException e) {
            if (choices.failedText == null && choices.compiledText != null) {
                console.note("cannot read " + source + " (" + e.getMessage()
                        + "); running the version compiled before");
                return true;
            }
            status.alert("Cannot read " + source + ": " + e.getMessage());
            return false;
        }
        if (now.equals(choices.compiledText) && choices.failedText == null) {
            return true;
        }
        if (now.equals(choices.failedText)) {
            console.error(source.getFileName() + " still does not compile (" + choices.failedError
                    + "); nothing runs until it"
                    + " does: the last version that compiled is not your file as it is now");
            status.alert(source.getFileName() + " does not compile: " + choices.failedError
                    + ". Fix it, then Start (F5);"
                    + " until then nothing runs");
            return false;
        }
        console.note(source.getFileName() + " changed since it was compiled: compiling it again for this run");
        return compileAndUse(source);
    }

    /** @return a note when the running controller's {@code .java} changed since it was compiled, or null */
    String staleNote() {
        Path source = choices.javaSource;
        if (source == null || choices.compiledText == null || !choices.controllerName.equals(choices.sourceClass)) {
            return null;
        }
        try {
            return Files.readString(source).equals(choices.compiledText)
                    ? null : source.getFileName() + " changed since this run"
                    + " started: the run goes on with the version it started with; Reset (F9) and Start (F5)"
                    + " run the change";
        } catch (IOException e) {
            return null;
        }
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
