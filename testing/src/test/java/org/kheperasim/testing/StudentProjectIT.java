package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The student project template (docs/examples/student-project) works as its README says, on a machine
 * where the simulator was installed once: a copy of it, built by a Maven of its own against this build's
 * artifacts in a fresh local repository, offline, fails its second test with the message the README shows
 * and passes the first; after the README's one change to the controller, graded as the course's CI does
 * (the instructor's script copies the course's build file, arena and hidden tests in and runs mvn test),
 * every test passes.
 */
@Timeout(value = 900, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class StudentProjectIT {
    private static final Path TEMPLATE = Fixtures.repoRoot().resolve("docs/examples/student-project");
    private static final String TEST = "assignment.MyControllerTest";

    @Test
    void aStudentClonesTestsReadsTheFailureChangesTheControllerAndPasses(@TempDir Path dir) throws Exception {
        checkTemplatePinsThisBuildsVersions();
        String version = System.getProperty("kheperasim.version");
        Path project = copy(TEMPLATE, dir.resolve("assignment"), true);
        NestedMaven maven = new NestedMaven(dir, Path.of(System.getProperty("kheperasim.outerRepository",
                System.getProperty("user.home") + "/.m2/repository")));
        LocalRepository.install(Fixtures.repoRoot(), version, maven.repository());

        // mvn test, as cloned: the lab test passes, the corridor test fails with its message.
        NestedMaven.Result first = maven.run(project, "test");
        assertNotEquals(0, first.exit(), "the template's second test is meant to fail:\n" + first.log());
        Map<String, String> results = results(project, TEST);
        assertEquals("passed", results.get("neverTouchesAWallInTheLab"), first.log());
        String message = results.get("reachesTheGoalWithinHalfAMinute");
        assertTrue(message.startsWith("MyController entered region 'goal' too late, at "), message + "\n" + first.log());
        assertTrue(message.contains("\n  expected: to enter region 'goal' (x 1000.0..1219.2 mm, y 0.0..400.0 mm) before 30.000 s\n"),
                message);
        assertTrue(message.contains("\n  happened: first entered at "), message);
        Matcher trace = Pattern.compile("\n  trace:    (\\S+)").matcher(message);
        assertTrue(trace.find(), message);
        assertEquals("target/kheperasim-runs/MyControllerTest/reachesTheGoalWithinHalfAMinute/corridor-MyController-seed1.trace",
                trace.group(1));
        assertTrue(Files.isRegularFile(project.resolve(trace.group(1))), "the trace the message names is there");
        assertTrue(first.log().contains(message.lines().findFirst().orElseThrow()), "Maven's output shows the message");
        String readme = Files.readString(TEMPLATE.resolve("README.md"));
        // The README shows it in a code block of its numbered list, indented by three spaces.
        String shown = String.join("\n", message.lines().map(l -> "   " + l).toList());
        assertTrue(readme.contains(shown), "the README shows the failure message as mvn test prints it; now it is:\n"
                + message);

        // The README's change; then the course grades it: its script copies its hidden tests in and runs them.
        Path controller = project.resolve("src/main/java/assignment/MyController.java");
        String before = "static final int SPEED = 2;";
        String after = "static final int SPEED = 5;";
        assertTrue(readme.contains(before) && readme.contains(after), "the README says to change '" + before + "' to '"
                + after + "'");
        Files.writeString(controller, Files.readString(controller).replace(before, after));
        Path course = dir.resolve("course");
        copy(TEMPLATE, course, false);
        NestedMaven.Result second = maven.exec(project, List.of("sh", course.resolve("instructor/grade-submission.sh").toString(),
                project.toString()), Map.of("MVN", String.join(" ", maven.mvn())));
        assertEquals(0, second.exit(), second.log());
        assertTrue(results(project, TEST).values().stream().allMatch("passed"::equals), second.log());
        Map<String, String> graded = results(project, "assignment.GradingTest");
        assertEquals(6, graded.size(), graded.toString());
        assertTrue(graded.values().stream().allMatch("passed"::equals), graded.toString());

        System.out.printf(Locale.ROOT, "StudentProjectIT: first mvn test (fresh local repository) %.1f s, after the change"
                + " with the hidden tests %.1f s%n", first.seconds(), second.seconds());
    }

    /** The template pins the plugin and library versions this build uses (the nested build finds only those offline). */
    private static void checkTemplatePinsThisBuildsVersions() throws IOException {
        String pom = Files.readString(TEMPLATE.resolve("pom.xml"));
        Map<String, String> pinned = new LinkedHashMap<>();
        pinned.put("<kheperasim.version>" + System.getProperty("kheperasim.version") + "</kheperasim.version>", "the simulator");
        pinned.put("<junit.version>" + System.getProperty("kheperasim.junitVersion") + "</junit.version>", "JUnit");
        pinned.put("<artifactId>maven-surefire-plugin</artifactId>\n        <version>" + System.getProperty("kheperasim.surefireVersion"),
                "surefire");
        pinned.put("<artifactId>maven-compiler-plugin</artifactId>\n        <version>" + System.getProperty("kheperasim.compilerVersion"),
                "the compiler plugin");
        pinned.put("<artifactId>maven-resources-plugin</artifactId>\n        <version>"
                + System.getProperty("kheperasim.resourcesVersion"), "the resources plugin");
        pinned.forEach((text, what) -> assertTrue(pom.contains(text), "docs/examples/student-project/pom.xml must pin the "
                + what + " version the build uses: " + text));
    }

    /**
     * A copy of the template: as a student clones it (without the instructor's folder), or as the course keeps
     * it (with it); never its build output.
     */
    private static Path copy(Path template, Path to, boolean student) throws IOException {
        try (Stream<Path> files = Files.walk(template)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path rel = template.relativize(f);
                if (student && rel.startsWith("instructor") || rel.startsWith("target")) {
                    continue;
                }
                Path dest = to.resolve(rel.toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(dest);
                } else {
                    Files.copy(f, dest);
                }
            }
        }
        return to;
    }

    /** @return each test of the class: "passed", or its failure's message */
    private static Map<String, String> results(Path project, String testClass) throws Exception {
        Path xml = project.resolve("target/surefire-reports/TEST-" + testClass + ".xml");
        assertTrue(Files.isRegularFile(xml), "no test report " + xml);
        Element suite = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(xml.toFile()).getDocumentElement();
        Map<String, String> out = new LinkedHashMap<>();
        NodeList cases = suite.getElementsByTagName("testcase");
        for (int i = 0; i < cases.getLength(); i++) {
            Element c = (Element) cases.item(i);
            NodeList failures = c.getElementsByTagName("failure");
            NodeList errors = c.getElementsByTagName("error");
            Element bad = failures.getLength() > 0 ? (Element) failures.item(0)
                    : errors.getLength() > 0 ? (Element) errors.item(0) : null;
            out.put(c.getAttribute("name"), bad == null ? "passed" : bad.getAttribute("message"));
        }
        return out;
    }
}
