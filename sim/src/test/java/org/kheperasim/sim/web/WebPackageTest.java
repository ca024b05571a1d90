package org.kheperasim.sim.web;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.awt.Color;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.gui.ArenaRenderer;
import org.kheperasim.sim.gui.SensorRenderer;

/** The web page's package: headless like the engine, and drawn in the window's colours. */
class WebPackageTest {

    @Test
    void thePageWriterWorksHeadlessAndBelowTheWindowAndTheCommandLine() {
        JavaClasses web = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.kheperasim.sim.web");
        noClasses().that().resideInAPackage("..sim.web..")
                .should().dependOnClassesThat().resideInAnyPackage("java.awt..", "javax.swing..", "..sim.gui..", "..sim.cli..",
                        "..sim.grade..")
                .because("run, grade and the window all write pages, headless; the page draws in the browser")
                .check(web);
    }

    @Test
    void thePageUsesTheWindowsColours() throws IOException {
        String js;
        try (InputStream in = RunPage.class.getResourceAsStream("page.js")) {
            js = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        String[][] named = {{"floor", hex(ArenaRenderer.FLOOR)}, {"outside", hex(ArenaRenderer.OUTSIDE)},
            {"wall", hex(ArenaRenderer.WALL)}, {"robot", hex(ArenaRenderer.ROBOT)}, {"cap", hex(ArenaRenderer.CAP)},
            {"lamp", hex(ArenaRenderer.LAMP)}, {"selection", hex(ArenaRenderer.SELECTION)}, {"prox", hex(SensorRenderer.PROX)},
            {"light", hex(SensorRenderer.LIGHT)}};
        for (String[] c : named) {
            assertTrue(js.contains(c[0] + ": '" + c[1] + "'"), c[0] + " is " + c[1] + " in the window; the page must agree");
        }
    }

    private static String hex(Color c) {
        return String.format(Locale.ROOT, "#%06X", c.getRGB() & 0xFFFFFF);
    }
}
