package org.kheperasim.sim.grade.platform;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * The platforms {@code grade --format} writes for, and where: {@code OUT/FORMAT/STUDENT/FILE}, one
 * folder per submission (a platform grades one submission at a time; its script copies the file to
 * where the platform reads it).
 */
public enum PlatformFormat {
    /** Gradescope's {@code results.json}. */
    GRADESCOPE("results.json"),
    /** PrairieLearn's {@code results.json}. */
    PRAIRIELEARN("results.json"),
    /** GitHub Classroom's runner result (the reporter takes it base64). */
    CLASSROOM("result.json"),
    /** What CodeGrade's custom test prints. */
    CODEGRADE("output.txt");

    private final String file;

    PlatformFormat(String file) {
        this.file = file;
    }

    /** @return its name on the command line, e.g. {@code gradescope} */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @return the file it writes in each submission's folder */
    public String file() {
        return file;
    }

    /**
     * @param words names, each possibly a comma-separated list
     * @return the formats, in order, once each
     * @throws IllegalArgumentException naming a word that is none, and the ones there are
     */
    public static Set<PlatformFormat> parse(List<String> words) {
        Set<PlatformFormat> out = new LinkedHashSet<>();
        for (String w : words) {
            for (String one : w.split(",")) {
                String s = one.strip().toLowerCase(Locale.ROOT);
                if (s.isEmpty()) {
                    continue;
                }
                out.add(Arrays.stream(values()).filter(f -> f.word().equals(s)).findFirst().orElseThrow(() ->
                        new IllegalArgumentException("--format " + one.strip()
                                + ": not a platform; give one or more of "
                                + String.join(", ", Arrays.stream(values()).map(PlatformFormat::word).toList())
                                + ", e.g. --format gradescope,prairielearn")));
            }
        }
        return out;
    }

    /** @param student a submission's name @return the folder name its files go in */
    public static String folder(String student) {
        String s = student.replaceAll("[^A-Za-z0-9_.-]", "_");
        return s.isEmpty() || s.startsWith(".") ? "_" + s : s;
    }

    /**
     * Writes each format's file for each submission.
     *
     * @param results          the submissions' results
     * @param formats          the formats
     * @param reportDir        the report folder (its pictures are there, and the files go under it)
     * @param executionSeconds the grading's real seconds
     * @return the files written
     */
    public static List<Path> writeAll(List<PlatformResult> results, Set<PlatformFormat> formats, Path reportDir,
            long executionSeconds) {
        List<Path> written = new ArrayList<>();
        try {
            for (PlatformFormat f : formats) {
                for (PlatformResult r : results) {
                    Path p = reportDir.resolve(f.word()).resolve(folder(r.student())).resolve(f.file);
                    Files.createDirectories(p.getParent());
                    AtomicFiles.write(p, f.text(r, reportDir, executionSeconds));
                    written.add(p);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the platforms' results in " + reportDir + ": "
                    + e.getMessage(), e);
        }
        return written;
    }

    /**
     * @param r                a submission's result
     * @param reportDir        the report folder, for its pictures
     * @param executionSeconds the grading's real seconds
     * @return this platform's file for it
     */
    public String text(PlatformResult r, Path reportDir, long executionSeconds) {
        return switch (this) {
            case GRADESCOPE -> GradescopeFormat.of(r, executionSeconds);
            case PRAIRIELEARN -> PrairieLearnFormat.of(r, reportDir);
            case CLASSROOM -> ClassroomFormat.of(r);
            case CODEGRADE -> CodeGradeFormat.of(r);
        };
    }
}
