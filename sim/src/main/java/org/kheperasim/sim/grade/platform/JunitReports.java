package org.kheperasim.sim.grade.platform;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.kheperasim.sim.text.Shown;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/**
 * A folder of JUnit XML reports (Maven Surefire's {@code target/surefire-reports/TEST-*.xml}: the
 * course's hidden tests run over a student's copy, docs/autograding.md) as one submission's result for
 * the platforms: a test per test case, its points when it passed, its failure's message and first lines
 * otherwise. No report, or no test case in one, is "not gradable" (the tests did not run: the build
 * failed first, most often because the code does not compile). JUnit XML holds no points and no
 * pictures: every test case is worth the same ({@code --points}).
 */
public final class JunitReports {
    /** Lines of a failure's stack trace kept in a test's output. */
    private static final int TRACE_LINES = 8;
    /** The largest report file read, bytes. */
    private static final long MAX_BYTES = 64L << 20;

    private JunitReports() {
    }

    /**
     * @param dir     the reports' folder
     * @param student the submission's name
     * @param points  each test case's points
     * @param hidden  true when the students must not see the tests
     * @return the submission's result
     */
    public static PlatformResult read(Path dir, String student, double points, boolean hidden) {
        List<Path> files = new ArrayList<>();
        if (Files.isDirectory(dir)) {
            try (Stream<Path> s = Files.list(dir)) {
                s.filter(p -> p.getFileName().toString().endsWith(".xml")).sorted().forEach(files::add);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read " + dir + ": " + e.getMessage(), e);
            }
        }
        List<PlatformTest> tests = new ArrayList<>();
        for (Path f : files) {
            tests.addAll(cases(f, points, hidden, tests.size()));
        }
        if (tests.isEmpty()) {
            String problem = "no JUnit test case in " + Shown.visible(dir.toString())
                    + ": the tests did not run (the build"
                    + " failed first; most often the code does not compile: see the build's log)";
            return new PlatformResult(student, List.of(), false, problem, List.of(), "not gradable: " + problem);
        }
        long passed = tests.stream().filter(PlatformTest::passed).count();
        String summary = String.format(Locale.ROOT, "%s: %d of %d tests passed, %s of %s points",
                Shown.line(student), passed,
                tests.size(), org.kheperasim.sim.grade.ReportFiles.num(
                        tests.stream().mapToDouble(PlatformTest::score).sum()),
                org.kheperasim.sim.grade.ReportFiles.num(points * tests.size()));
        return new PlatformResult(student, tests, true, "", List.of(), summary);
    }

    private static List<PlatformTest> cases(Path file, double points, boolean hidden, int before) {
        Document doc;
        try {
            if (Files.size(file) > MAX_BYTES) {
                throw new IllegalArgumentException(file + " is over " + (MAX_BYTES >> 20) + " MiB: not a JUnit report");
            }
            doc = parser().parse(file.toFile());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + file + ": " + e.getMessage(), e);
        } catch (SAXException e) {
            throw new IllegalArgumentException(file + " is not a JUnit XML report: " + e.getMessage(), e);
        }
        List<PlatformTest> out = new ArrayList<>();
        NodeList cases = doc.getElementsByTagName("testcase");
        for (int i = 0; i < cases.getLength(); i++) {
            Element c = (Element) cases.item(i);
            String cls = c.getAttribute("classname");
            String name = (cls.isEmpty() ? "" : cls.substring(cls.lastIndexOf('.') + 1) + ".") + c.getAttribute("name");
            Element failure = first(c, "failure");
            Element error = first(c, "error");
            Element skipped = first(c, "skipped");
            String status = failure != null ? "failed" : error != null ? "error" : skipped != null
                    ? "skipped" : "passed";
            boolean passed = "passed".equals(status);
            Element why = failure != null ? failure : error != null ? error : skipped;
            String output = passed ? "passed" : status + ": " + text(why);
            out.add(new PlatformTest(Shown.line(name), "1." + (before + out.size() + 1),
                    passed ? points : 0, points, passed,
                    status, output, hidden, "", Shown.line(cls)));
        }
        return out;
    }

    private static String text(Element why) {
        StringBuilder sb = new StringBuilder(Shown.line(why.getAttribute("message")));
        List<String> lines = Shown.lines(why.getTextContent().strip());
        for (int i = 0; i < StrictMath.min(TRACE_LINES, lines.size()); i++) {
            if (!lines.get(i).isBlank()) {
                sb.append('\n').append(lines.get(i));
            }
        }
        return sb.toString();
    }

    private static Element first(Element parent, String tag) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(tag)) {
                return e;
            }
        }
        return null;
    }

    /** A parser that reads no DTD and no external entity (a report is the student's build's output). */
    private static DocumentBuilder parser() {
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setExpandEntityReferences(false);
            f.setXIncludeAware(false);
            return f.newDocumentBuilder();
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("no XML parser: " + e.getMessage(), e);
        }
    }
}
