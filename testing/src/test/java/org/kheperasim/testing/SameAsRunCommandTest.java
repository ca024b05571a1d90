package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A run made through the testing API is the run {@code khepera-sim run} makes with the same arena,
 * controllers, seed and settings: the command, in a JVM of its own, writes a byte-identical trace and
 * reports the same poses, controller ends, regions and score. The command line compared is the one the
 * API itself prints ({@link Run#commandLine()}), so that line is checked too.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SameAsRunCommandTest {
    private static final Pattern NUMBER = Pattern.compile("-?[0-9.]+(?:[eE][-+]?\\d+)?");

    @Test
    void aStudentsControllerWithSettingsInABundledArena(@TempDir Path dir) throws Exception {
        Run api = Run.of(student.Avoider.class).in("maze").seconds(60).seed(7).set("noise.reading", "0.5")
                .set("link.baud", "115200").run();
        String json = runCommand(api, dir);
        assertSame(api, json, dir);
    }

    @Test
    void severalRobotsWithTheirOwnControllersAndSettingsInAnArenaFile(@TempDir Path dir) throws Exception {
        Run api = Run.of(student.Avoider.class).in(Fixtures.resource("head-on.arena")).seconds(30).seed(11)
                .robot(1, "Braitenberg").robot(3, student.Thrower.class).robotSetting(2, "motor.left.calibration", "0.8")
                .sampleEvery(KheperaAssertions.millis(20)).run();
        assertEquals(Ending.Kind.THREW, api.robot(3).ending().kind());
        String json = runCommand(api, dir);
        assertSame(api, json, dir);
    }

    /** Runs the command the API prints, in a JVM of its own, with --json; returns its standard output. */
    private static String runCommand(Run api, Path dir) throws IOException, InterruptedException {
        String line = api.commandLine();
        assertTrue(line.startsWith("java -jar khepera-sim.jar run "), line);
        // The quick compiler only: the JVM lives a second or two, and C2 would spend most of its processor time.
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "org.kheperasim.sim.cli.Main"));
        for (String word : line.substring("java -jar khepera-sim.jar ".length()).split(" ")) {
            cmd.add(word.startsWith("'") ? word.substring(1, word.length() - 1) : word);
        }
        cmd.addAll(List.of("--trace", dir.resolve("command.trace").toString(), "--json", "--quiet"));
        Process p = new ProcessBuilder(cmd).redirectOutput(dir.resolve("out.json").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
        assertTrue(p.waitFor(240, TimeUnit.SECONDS), "the run command did not end");
        String out = Files.readString(dir.resolve("out.json"));
        assertTrue(out.startsWith("{"), out + Files.readString(dir.resolve("err.txt")));
        return out;
    }

    private static void assertSame(Run api, String json, Path dir) throws Exception {
        String trace = Files.readString(dir.resolve("command.trace"));
        assertEquals(trace, api.trace(), "the traces are byte-identical");
        assertEquals(sha256(api.trace()), string(json, "traceSha256"));
        assertEquals(api.duration().seconds(), number(json, "simulatedSeconds"), 1e-9);
        List<String> robots = objects(json.substring(json.indexOf("\"robots\":[")));
        assertEquals(api.robots().size(), robots.size());
        for (int i = 0; i < robots.size(); i++) {
            RobotRun r = api.robot(i);
            String o = robots.get(i);
            Pose end = r.finalPose();
            assertEquals(end.x(), number(o, "x"), 1e-3, "robot " + i + " x");
            assertEquals(end.y(), number(o, "y"), 1e-3, "robot " + i + " y");
            assertEquals(end.headingDeg(), number(o, "headingDeg"), 1e-3, "robot " + i + " heading");
            assertEquals(r.distanceMm(), number(o, "distanceMm"), 1e-6 * Math.max(1, r.distanceMm()));
            assertEquals(r.collisions(), (int) number(o, "collisions"));
            assertEquals(r.visitedPercent(), number(o, "visitedPercent"), 1e-6 * Math.max(1, r.visitedPercent()));
            String status = string(o, "controllerStatus");
            assertEquals(switch (r.ending().kind()) {
                case RAN_TO_THE_END -> "stopped";
                case RETURNED -> "finished";
                case THREW -> "failed";
                default -> r.ending().kind().name().toLowerCase(Locale.ROOT);
            }, status, "robot " + i);
        }
        if (api.score().max() > 0) {
            String score = json.substring(json.indexOf("\"score\":"));
            assertEquals(api.score().points(), number(score, "points"), 1e-6 * Math.max(1, api.score().points()));
            assertEquals(api.score().max(), number(score, "max"), 1e-9);
        }
        String entered = json.substring(json.indexOf("\"regionsEntered\":{") + 18, json.indexOf('}', json.indexOf("\"regionsEntered\":{")));
        List<String> names = new ArrayList<>();
        for (String pair : entered.isEmpty() ? new String[0] : entered.split(",")) {
            String name = pair.substring(1, pair.indexOf('"', 1));
            names.add(name);
            assertEquals(api.robot().entered(name).orElseThrow().seconds(), Double.parseDouble(pair.substring(pair.indexOf(':') + 1)),
                    1e-6, name);
        }
        assertEquals(List.copyOf(api.robot().regionsEntered().keySet()), names);
    }

    private static String sha256(String text) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
    }

    private static String string(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":\"([^\"]*)\"").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1);
    }

    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(" + NUMBER.pattern() + ")").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return Double.parseDouble(m.group(1));
    }

    /** The objects of a JSON array of flat objects, each as its text. */
    private static List<String> objects(String array) {
        List<String> out = new ArrayList<>();
        int end = array.indexOf(']');
        for (int i = array.indexOf('{'); i >= 0 && i < end; i = array.indexOf('{', i + 1)) {
            out.add(array.substring(i, array.indexOf('}', i) + 1));
        }
        return out;
    }
}
