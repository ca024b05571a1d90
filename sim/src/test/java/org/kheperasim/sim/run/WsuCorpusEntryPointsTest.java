package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.reflect.Modifier;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;

/**
 * How many of the public WSU course code's entry points run headless and untrusted: the figures of
 * docs/wsu-migration.md ("What runs"). Each set is compiled unchanged (or, for shipped class files,
 * taken as it is), every concrete controller class in it (a {@code RobotController} subclass, a
 * {@code Controller} of this API, or an Appendix-style {@code Thread}) is run for 10 simulated
 * seconds in the lab, contained, and the counts are printed per set with each failure's first line.
 * The code is not part of this project: {@code -Dkheperasim.wsuCorpus=DIR} holds clones of
 * Habitats/khepera (as {@code khepera}), Nepetalactone/Systemarchitekturen-FHV,
 * christianLins/KheperaRobotControl, henrihs/stupid-robot and Elliot-TS/Modified-WSU-Khepera-Simulator;
 * without it the test is skipped. The original simulator's sources that some sets carry
 * ({@code edu/wsu/KheperaSimulator}) are left out.
 */
public class WsuCorpusEntryPointsTest {
    @TempDir
    Path dir;

    /** Set name to folder; a folder ending in {@code controllers} holds shipped class files. */
    public static final Map<String, String> SETS = new LinkedHashMap<>();

    static {
        SETS.put("habitats", "khepera/src");
        SETS.put("habitats-jorgen", "khepera/extra/old/jorgen");
        SETS.put("habitats-olav", "khepera/extra/old/olav");
        SETS.put("habitats-pat", "khepera/extra/old/pat");
        SETS.put("fhv-ue4", "Systemarchitekturen-FHV/ue4/WSU_KSuite_1.1.2/src");
        SETS.put("fhv-ue4-source", "Systemarchitekturen-FHV/ue4/WSU_KSuite_1.1.2/source");
        SETS.put("fhv-ue5", "Systemarchitekturen-FHV/ue5/RobotControl/src");
        SETS.put("fhv-ue5-source", "Systemarchitekturen-FHV/ue5/RobotControl/source");
        SETS.put("lins", "KheperaRobotControl/RobotControl1/src");
        SETS.put("henrihs", "stupid-robot/src");
        SETS.put("elliot-source", "Modified-WSU-Khepera-Simulator/source");
        SETS.put("elliot-classes", "Modified-WSU-Khepera-Simulator/controllers");
    }

    /**
     * Class files a set's shipped classes need that the fork ships beside its simulator, not with
     * them: the vehicles' base {@code VehicleController} (the fork's own class, in
     * {@code classes/edu/wsu/KheperaSimulator}, where the fork's {@code run.sh} finds it). Only that
     * file is put on the set's classpath, in a folder of its own, never the original's classes.
     */
    private static final Map<String, String> SHIPPED_BESIDE = Map.of("elliot-classes",
            "Modified-WSU-Khepera-Simulator/classes/edu/wsu/KheperaSimulator/VehicleController.class");

    @Test
    void countTheEntryPointsThatRunHeadlessUntrusted() throws Exception {
        String p = System.getProperty(WsuCorpusTest.PROPERTY);
        Assumptions.assumeTrue(p != null && !p.isBlank(), "no -D" + WsuCorpusTest.PROPERTY + "=DIR: the public course code is not here");
        Path corpus = Path.of(p);
        int total = 0;
        int ran = 0;
        for (Map.Entry<String, String> set : SETS.entrySet()) {
            Path src = corpus.resolve(set.getValue());
            if (!Files.isDirectory(src)) {
                System.out.printf("%-16s missing%n", set.getKey());
                continue;
            }
            Path classes = src.endsWith("controllers") ? src : compile(src, Files.createDirectories(dir.resolve(set.getKey())));
            List<Path> classpath = new ArrayList<>(List.of(classes));
            String beside = SHIPPED_BESIDE.get(set.getKey());
            if (beside != null && Files.isRegularFile(corpus.resolve(beside))) {
                Path base = dir.resolve(set.getKey() + "-beside");
                Path to = base.resolve(beside.substring(beside.indexOf("/classes/") + "/classes/".length()));
                Files.createDirectories(to.getParent());
                Files.copy(corpus.resolve(beside), to);
                classpath.add(base);
            }
            List<String> entries = entryPoints(classes, classpath);
            List<String> failures = new ArrayList<>();
            for (String e : entries) {
                String why = run(classpath, e);
                if (why != null) {
                    failures.add(e + ": " + why);
                }
            }
            total += entries.size();
            ran += entries.size() - failures.size();
            System.out.printf("%-16s %d entry points, %d run headless untrusted%n", set.getKey(), entries.size(),
                    entries.size() - failures.size());
            failures.forEach(f -> System.out.println("    " + f));
        }
        System.out.printf("all sets: %d entry points, %d run headless untrusted%n", total, ran);
        assertTrue(total > 0, "the corpus holds controllers: " + corpus);
    }

    /** @return null when it ran its 10 s without failing, else the first line of why not */
    private static String run(List<Path> classpath, String controller) {
        try {
            RunResult r = Simulation.builder().arena("lab").classpath(classpath).controller(controller).seed(1)
                    .seconds(10).console(l -> { }).run();
            return r.first().status().failed() ? firstLine(r.first().failure()) : null;
        } catch (ControllerException | LinkageError | IllegalStateException e) {
            return firstLine(e.getMessage());
        }
    }

    private static String firstLine(String s) {
        String t = s == null ? "" : s.lines().findFirst().orElse("");
        return t.length() > 300 ? t.substring(0, 300) + "…" : t;
    }

    private static Path compile(Path src, Path out) throws IOException {
        List<String> args = new ArrayList<>(List.of("-nowarn", "-encoding", "ISO-8859-1", "-proc:none", "--release", "17",
                "-cp", System.getProperty("java.class.path"), "-d", out.toString()));
        try (Stream<Path> files = Files.walk(src)) {
            files.filter(f -> f.toString().endsWith(".java"))
                    .filter(f -> !src.relativize(f).toString().replace('\\', '/').startsWith("edu/wsu/KheperaSimulator/"))
                    .forEach(f -> args.add(f.toString()));
        }
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        int rc = ToolProvider.getSystemJavaCompiler().run(null, quiet, quiet, args.toArray(new String[0]));
        assertTrue(rc == 0, src + " compiles unchanged");
        return out;
    }

    /** @return the concrete controller classes (top-level and static nested) under the folder, sorted */
    private static List<String> entryPoints(Path classes, List<Path> classpath) throws IOException {
        List<String> names = new ArrayList<>();
        URL[] urls = new URL[classpath.size()];
        for (int i = 0; i < urls.length; i++) {
            urls[i] = classpath.get(i).toUri().toURL();
        }
        try (Stream<Path> files = Files.walk(classes); URLClassLoader look = new URLClassLoader(urls,
                WsuCorpusEntryPointsTest.class.getClassLoader())) {
            for (Path f : files.filter(x -> x.toString().endsWith(".class")).sorted().toList()) {
                String name = classes.relativize(f).toString().replace('\\', '/').replaceFirst("\\.class$", "").replace('/', '.');
                if (name.contains("$")) {
                    continue;
                }
                try {
                    Class<?> c = Class.forName(name, false, look);
                    if (!Modifier.isAbstract(c.getModifiers()) && Modifier.isPublic(c.getModifiers()) && isController(c)) {
                        names.add(name);
                    }
                } catch (ClassNotFoundException | LinkageError e) {
                    // Shipped class files too new for this JVM: judged by their superclass's name below.
                    if (e instanceof UnsupportedClassVersionError && controllerByFile(f)) {
                        names.add(name);
                    }
                }
            }
        }
        return names;
    }

    private static boolean isController(Class<?> c) {
        if (edu.wsu.KheperaSimulator.RobotController.class.isAssignableFrom(c)
                || org.kheperasim.api.Controller.class.isAssignableFrom(c)) {
            return true;
        }
        if (Thread.class.isAssignableFrom(c)) {
            try {
                c.getConstructor(org.kheperasim.api.CurrentRobotState.class, org.kheperasim.api.MessagePasser.class);
                return true;
            } catch (NoSuchMethodException | LinkageError e) {
                return false;
            }
        }
        return false;
    }

    /** A class file this JVM cannot load: a controller when it names the WSU API's base classes. */
    private static boolean controllerByFile(Path f) throws IOException {
        String text = new String(Files.readAllBytes(f), java.nio.charset.StandardCharsets.ISO_8859_1);
        return text.contains("edu/wsu/KheperaSimulator/RobotController") || text.contains("edu/wsu/KheperaSimulator/VehicleController");
    }
}
