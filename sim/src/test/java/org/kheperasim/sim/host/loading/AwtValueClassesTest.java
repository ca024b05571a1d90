package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The {@code java.awt} value classes the allowlist allows load no toolkit: in a fresh headless JVM,
 * using {@code Point} and the {@code java.awt.geom} values loads neither the {@code Toolkit} class
 * nor the AWT library; using {@code Rectangle}, {@code Dimension} or {@code Color} initialises the
 * {@code Toolkit} class and loads the JDK's AWT library (their class initializers do), but creates
 * no toolkit (no toolkit implementation class is loaded), starts no AWT thread and opens no display.
 */
class AwtValueClassesTest {
    /** What the child JVM runs: it uses the classes named, then prints what was loaded. */
    public static void main(String[] args) throws IOException {
        for (String a : args) {
            switch (a) {
                case "Point" -> System.out.println(new java.awt.Point(1, 2).distance(3, 4));
                case "geom" -> System.out.println(new java.awt.geom.Point2D.Double(1, 2).distance(new java.awt.geom.Point2D.Float(3, 4))
                        + new java.awt.geom.Line2D.Double(0, 0, 1, 1).ptSegDist(0, 1)
                        + new java.awt.geom.Line2D.Float(0, 0, 1, 1).getBounds2D().getWidth()
                        + java.awt.geom.AffineTransform.getRotateInstance(1).getScaleX());
                case "Rectangle" -> System.out.println(new java.awt.Rectangle(0, 0, 4, 4).union(new java.awt.Rectangle(1, 1)));
                case "Dimension" -> System.out.println(new java.awt.Dimension(3, 4).getWidth());
                case "Color" -> System.out.println(java.awt.Color.RED.darker().getRGB() + java.awt.Color.decode("#102030").getBlue());
                default -> throw new IllegalArgumentException(a);
            }
        }
        boolean library = Files.readString(Path.of("/proc/self/maps")).contains("libawt");
        List<String> awtThreads = Thread.getAllStackTraces().keySet().stream().map(Thread::getName)
                .filter(n -> n.startsWith("AWT")).toList();
        System.out.println("awt-library=" + library + " awt-threads=" + awtThreads);
    }

    /** @return the child's output: its class loading (-verbose:class) and its last line */
    private static String probe(String... uses) throws IOException, InterruptedException {
        List<String> command = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-Xlog:class+load=info", "-cp", System.getProperty("java.class.path"),
                AwtValueClassesTest.class.getName()));
        command.addAll(List.of(uses));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().remove("DISPLAY");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the child JVM ends");
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    private static boolean loaded(String out, String className) {
        return out.lines().anyMatch(l -> l.contains(" " + className + " "));
    }

    @Test
    void pointAndTheGeomValuesLoadNeitherTheToolkitNorTheAwtLibrary() throws Exception {
        String out = probe("Point", "geom");
        assertFalse(loaded(out, "java.awt.Toolkit"), "java.awt.Toolkit not loaded");
        assertTrue(out.contains("awt-library=false awt-threads=[]"), out.lines().reduce((a, b) -> b).orElse(""));
    }

    @Test
    void rectangleDimensionAndColorLoadTheAwtLibraryButCreateNoToolkit() throws Exception {
        String out = probe("Rectangle", "Dimension", "Color");
        assertTrue(loaded(out, "java.awt.Toolkit"), "their class initializers call Toolkit.loadLibraries()");
        for (String toolkit : List.of("sun.awt.HeadlessToolkit", "sun.awt.SunToolkit", "sun.awt.X11.XToolkit",
                "sun.awt.X11GraphicsEnvironment", "java.awt.EventQueue")) {
            assertFalse(loaded(out, toolkit), toolkit + " is not loaded: no toolkit is created");
        }
        assertTrue(out.contains("awt-library=true awt-threads=[]"), out.lines().reduce((a, b) -> b).orElse(""));
    }
}
