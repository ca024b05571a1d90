package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.gui.ArenaRenderer;
import org.kheperasim.sim.gui.ViewTransform;
import org.kheperasim.sim.replay.Replay;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.testfixtures.Arenas;

/**
 * A run's page in a real browser: loaded by headless Chromium, shown at a moment or played, its
 * picture compared with the window's drawing of the same moment ({@link ArenaRenderer} into an
 * image): each robot's centre, found by its colour, within 5 px, and the same walls. The pictures
 * are kept in {@code target/web-page-tests/} to look at.
 */
@Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunPageBrowserTest {
    private static final int W = 900;
    private static final int H = 700;

    @TempDir
    Path dir;

    private Chromium chromium() {
        return Chromium.require(getClass().getSimpleName(), dir.resolve("profiles"));
    }

    private static Path target() throws IOException {
        return Files.createDirectories(Path.of("target", "web-page-tests").toAbsolutePath());
    }

    private Path trace(String name, Arena arena, String controller, double seconds) {
        Path trace = dir.resolve(name + ".trace");
        Simulation.builder().arena(arena).controller(controller).seed(1).seconds(seconds).trace(trace).console(l -> { }).run();
        return trace;
    }

    @Test
    void aMomentOfTheMazeLooksAsTheWindowDrawsIt() throws Exception {
        Chromium browser = chromium();
        Path trace = trace("maze", ArenaFormat.loadBundled("maze"), "WallFollower", 120);
        Path page = dir.resolve("maze.html");
        RunPage.write(trace, page);
        double t = 77.37;
        compare(browser, page, ReplayFiles.open(trace), t, "maze");
    }

    @Test
    void threeRobotsAtAMomentAreWhereTheWindowDrawsThem() throws Exception {
        Chromium browser = chromium();
        Path trace = trace("three", Arenas.THREE, "Braitenberg", 60);
        Path page = dir.resolve("three.html");
        RunPage.write(trace, Arenas.THREE, RunOutcome.none(), page);
        compare(browser, page, ReplayFiles.open(trace, Arenas.THREE), 41.02, "three");
    }

    @Test
    void theSensorPanelShowsTheValuesOfThatMoment() throws Exception {
        Chromium browser = chromium();
        Path trace = trace("maze", ArenaFormat.loadBundled("maze"), "WallFollower", 60);
        Path page = dir.resolve("maze.html");
        RunPage.write(trace, page);
        Replay replay = ReplayFiles.open(trace);
        double t = 33.3;
        String dom = browser.dom(page, "t=" + t, 1280, 800, 500);
        RobotView r = replay.at(t).robots().get(0);
        StringBuilder want = new StringBuilder("robot 0 at 33.300 s: proximity");
        for (int i = 0; i < 8; i++) {
            want.append(' ').append(r.proximity(i));
        }
        want.append("; light");
        for (int i = 0; i < 8; i++) {
            want.append(' ').append(r.light(i));
        }
        want.append(String.format(Locale.ROOT, "; speed %d %d; encoders %d %d; pose %.1f %.1f %.1f;", r.speedLeft(),
                r.speedRight(), r.encoderLeft(), r.encoderRight(), r.x(), r.y(), r.headingDeg()));
        assertTrue(dom.contains(want), "the page's readings are not the trace's at " + t + " s: wanted\n" + want + "\nin\n" + readings(dom));
        assertEquals("33.300", Chromium.bodyData(dom, "t"));
        assertEquals("paused", Chromium.bodyData(dom, "state"));
    }

    @Test
    void playingMovesTheMomentOnAndStopsAtTheEnd() throws Exception {
        Chromium browser = chromium();
        Path trace = trace("lab", ArenaFormat.loadBundled("lab"), "Braitenberg", 30);
        Path page = dir.resolve("lab.html");
        RunPage.write(trace, page);
        String playing = browser.dom(page, "t=10&play=2", 1280, 800, 3000);
        assertEquals("playing", Chromium.bodyData(playing, "state"), playing);
        double reached = Double.parseDouble(Chromium.bodyData(playing, "t"));
        assertTrue(reached > 10.5 && reached < 30, "played from 10 s to " + reached + " s");
        String ended = browser.dom(page, "t=29&play=64", 1280, 800, 8000);
        assertEquals("30.000", Chromium.bodyData(ended, "t"), "played to the end");
        assertEquals("paused", Chromium.bodyData(ended, "state"));
        assertEquals(null, Chromium.bodyData(ended, "error"));
    }

    @Test
    void aControllerThatThrewIsMarkedWithItsTimeAndMessage() throws Exception {
        Chromium browser = chromium();
        RunPageRecorder recorder = new RunPageRecorder(ArenaFormat.loadBundled("lab"), null);
        RunResult result = Simulation.builder().arena("lab").controller("org.kheperasim.testcontrollers.Thrower").seed(2)
                .seconds(5).listener(recorder, RunPageRecorder.PERIOD_MILLIS).console(recorder::console).run();
        Path page = dir.resolve("thrower.html");
        RunPage.write(recorder, RunOutcome.of(result), page);
        String dom = browser.dom(page, "t=4", 1280, 800, 500);
        assertTrue(dom.matches("(?s).*<b>Thrower</b> threw at 1\\.0\\d\\d s<pre>[^<]*/ by zero.*"), dom);
        assertTrue(dom.contains("Thrower.java:24"), "the student's line is shown: " + dom);
        Files.copy(page, target().resolve("thrower.html"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    /** Shows the page at {@code t} with the arena alone in the window, draws the same moment as the window does, and compares. */
    private void compare(Chromium browser, Path page, Replay replay, double t, String name) throws Exception {
        Path shot = target().resolve(name + "-page.png");
        browser.screenshot(page, "only=arena&t=" + t, W, H, shot);
        BufferedImage pagePicture = ImageIO.read(shot.toFile());
        assertEquals(W, pagePicture.getWidth());
        BufferedImage window = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        ViewTransform view = new ViewTransform();
        Arena arena = replay.arenaAt(t);
        view.fit(arena.width(), arena.height(), W, H, 16);
        Snapshot s = replay.at(t);
        List<float[]> trails = new ArrayList<>();
        for (int i = 0; i < replay.robotCount(); i++) {
            trails.add(replay.trail(i, t));
        }
        Graphics2D g = window.createGraphics();
        ArenaRenderer.draw(g, view, W, H, arena, s, new ArenaRenderer.Overlay(Set.of(), null, null, trails),
                ArenaRenderer.Options.all());
        g.dispose();
        ImageIO.write(window, "png", target().resolve(name + "-window.png").toFile());
        for (RobotView r : s.robots()) {
            double[] expected = {view.sx(r.x()), view.sy(r.y())};
            double[] inPage = centre(pagePicture, expected);
            double[] inWindow = centre(window, expected);
            double apart = StrictMath.hypot(inPage[0] - inWindow[0], inPage[1] - inWindow[1]);
            assertTrue(apart <= 5, String.format(Locale.ROOT, "robot %d at %.2f s: the page draws it at (%.1f, %.1f) px, the"
                    + " window at (%.1f, %.1f) px (%s)", r.id(), t, inPage[0], inPage[1], inWindow[0], inWindow[1], shot));
        }
        Mask pageWalls = new Mask(pagePicture, ArenaRenderer.WALL);
        Mask windowWalls = new Mask(window, ArenaRenderer.WALL);
        assertTrue(windowWalls.count > 2000, "the window drew walls: " + windowWalls.count + " px");
        double recall = windowWalls.near(pageWalls);
        double precision = pageWalls.near(windowWalls);
        assertTrue(recall > 0.97 && precision > 0.97, String.format(Locale.ROOT, "walls: %.1f%% of the window's wall pixels"
                + " are walls in the page, %.1f%% of the page's are in the window (%s)", 100 * recall, 100 * precision, shot));
    }

    /** The centre of the robot-coloured pixels within 40 px of {@code near}. */
    private static double[] centre(BufferedImage img, double[] near) {
        double sx = 0;
        double sy = 0;
        int n = 0;
        for (int y = (int) near[1] - 40; y <= near[1] + 40; y++) {
            for (int x = (int) near[0] - 40; x <= near[0] + 40; x++) {
                if (x >= 0 && y >= 0 && x < img.getWidth() && y < img.getHeight() && close(img.getRGB(x, y), ArenaRenderer.ROBOT, 10)) {
                    sx += x + 0.5;
                    sy += y + 0.5;
                    n++;
                }
            }
        }
        assertTrue(n > 50, "no robot drawn near (" + near[0] + ", " + near[1] + "): " + n + " px of its colour");
        return new double[] {sx / n, sy / n};
    }

    private static boolean close(int rgb, Color c, int tolerance) {
        return StrictMath.abs((rgb >> 16 & 255) - c.getRed()) <= tolerance && StrictMath.abs((rgb >> 8 & 255) - c.getGreen()) <= tolerance
                && StrictMath.abs((rgb & 255) - c.getBlue()) <= tolerance;
    }

    private static String readings(String dom) {
        int i = dom.indexOf("id=\"readings\"");
        return i < 0 ? "(no readings)" : dom.substring(i, StrictMath.min(dom.length(), i + 400));
    }

    /** The pixels of one colour in a picture. */
    private static final class Mask {
        final boolean[][] on;
        final int count;

        Mask(BufferedImage img, Color c) {
            on = new boolean[img.getHeight()][img.getWidth()];
            int n = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    on[y][x] = close(img.getRGB(x, y), c, 14);
                    n += on[y][x] ? 1 : 0;
                }
            }
            count = n;
        }

        /** @return the share of this mask's pixels with one of {@code other}'s within a pixel */
        double near(Mask other) {
            int hit = 0;
            for (int y = 0; y < on.length; y++) {
                for (int x = 0; x < on[y].length; x++) {
                    if (on[y][x] && other.any(x, y)) {
                        hit++;
                    }
                }
            }
            return count == 0 ? 0 : hit / (double) count;
        }

        private boolean any(int x, int y) {
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    int yy = y + dy;
                    int xx = x + dx;
                    if (yy >= 0 && xx >= 0 && yy < on.length && xx < on[yy].length && on[yy][xx]) {
                        return true;
                    }
                }
            }
            return false;
        }
    }
}
