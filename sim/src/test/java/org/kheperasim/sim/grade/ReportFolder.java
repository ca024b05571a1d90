package org.kheperasim.sim.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/** What the grading tests compare of a report folder. */
final class ReportFolder {
    private ReportFolder() {
    }

    /**
     * @param folder a grading's output folder
     * @return its report's files, relative and sorted: not the work folder, the timings (real time) or the journal (its
     *     order is the order runs ended in)
     */
    static List<String> files(Path folder) throws IOException {
        try (Stream<Path> s = Files.walk(folder)) {
            return s.filter(Files::isRegularFile).map(p -> folder.relativize(p).toString().replace('\\', '/'))
                    .filter(p -> !p.startsWith("work/") && !p.equals("timings.csv") && !p.equals(Journal.FILE)).sorted().toList();
        }
    }

    /** @return {@code a} followed by {@code b} */
    static String[] concat(String[] a, String... b) {
        return Stream.concat(Stream.of(a), Stream.of(b)).toArray(String[]::new);
    }
}
