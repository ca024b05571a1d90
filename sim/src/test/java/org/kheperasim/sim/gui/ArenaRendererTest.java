package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.edit.Item;
import org.kheperasim.sim.edit.ItemHits;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/** The renderer draws into an image headless: things appear where the model says, in their colours. */
class ArenaRendererTest {
    private static final int SIZE = 500;

    /** A 1000 mm arena: one wall along y = 800 from x = 200 to 800, a cap at (200, 200), the robot start at (500, 300). */
    private static Arena arena() {
        return new Arena("t", 1000, 1000, List.of(new Pose(500, 300, 90)), List.of(new Wall(200, 800, 800, 800, 20)),
                List.of(), List.of(new Cap(200, 200, 15)), List.of());
    }

    private static BufferedImage render(Arena a, Snapshot s, ArenaRenderer.Overlay o) {
        BufferedImage img = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        ViewTransform v = view(a);
        ArenaRenderer.draw(g, v, SIZE, SIZE, a, s, o, new ArenaRenderer.Options(false, false, false, false));
        g.dispose();
        return img;
    }

    private static ViewTransform view(Arena a) {
        ViewTransform v = new ViewTransform();
        v.fit(a.width(), a.height(), SIZE, SIZE, 0);
        return v;
    }

    private static Color at(BufferedImage img, ViewTransform v, double x, double y) {
        return new Color(img.getRGB((int) v.sx(x), (int) v.sy(y)));
    }

    @Test
    void wallCapRobotAndFloorAreWhereTheModelSays() {
        Arena a = arena();
        BufferedImage img = render(a, null, ArenaRenderer.Overlay.NONE);
        ViewTransform v = view(a);
        assertEquals(0.5, v.scale(), 1e-9);
        assertEquals(ArenaRenderer.WALL, at(img, v, 500, 800), "the wall's middle");
        assertEquals(ArenaRenderer.FLOOR, at(img, v, 500, 850), "floor above the wall");
        assertEquals(ArenaRenderer.FLOOR, at(img, v, 100, 800), "floor beyond the wall's end");
        assertEquals(ArenaRenderer.CAP, at(img, v, 200, 200), "the cap's centre");
        Color robot = at(img, v, 490, 290);
        assertTrue(robot.getGreen() > robot.getRed() + 40, "the robot start is drawn green: " + robot);
        assertEquals(ArenaRenderer.FLOOR, at(img, v, 500, 500), "nothing between robot and wall");
    }

    @Test
    void aSnapshotDrawsTheRobotWhereItIsNowAndCapsWhereTheyAre() {
        Arena a = arena();
        RobotView r = new RobotView(0, "r", 700, 500, 0, 0, 0, 0, 0, Contact.NONE, new int[8], new int[8], 0, 0, "running",
                new GripperView(180, false, GripperState.OPEN, false, 0, -1), 0);
        Snapshot s = new Snapshot(1_000_000_000L, List.of(r), List.of(new CapView(0, 300, 300, 15, -1)));
        BufferedImage img = render(a, s, ArenaRenderer.Overlay.NONE);
        ViewTransform v = view(a);
        assertEquals(ArenaRenderer.ROBOT, at(img, v, 690, 490), "the robot where the snapshot puts it");
        assertEquals(ArenaRenderer.FLOOR, at(img, v, 490, 290), "not at its start");
        assertEquals(ArenaRenderer.CAP, at(img, v, 300, 300), "the cap where the snapshot puts it");
        assertEquals(ArenaRenderer.FLOOR, at(img, v, 200, 200), "not where the arena file had it");
    }

    @Test
    void theRobotsLedsAreDrawnLitOrDark() {
        Arena a = arena();
        ViewTransform v = view(a);
        // Heading 0: LED 0 sits 16 mm behind the centre and 6 mm to the left, LED 1 6 mm to the right.
        for (int leds = 0; leds < 4; leds++) {
            RobotView r = new RobotView(0, "r", 700, 500, 0, 0, 0, 0, 0, Contact.NONE, new int[8], new int[8], 0, 0,
                    "running", new GripperView(180, false, GripperState.OPEN, false, 0, -1), leds);
            BufferedImage img = render(a, new Snapshot(0, List.of(r), List.of()), ArenaRenderer.Overlay.NONE);
            assertEquals((leds & 1) != 0, at(img, v, 684, 506).equals(ArenaRenderer.LED_ON), "LED 0 with bits " + leds);
            assertEquals((leds & 2) != 0, at(img, v, 684, 494).equals(ArenaRenderer.LED_ON), "LED 1 with bits " + leds);
        }
    }

    @Test
    void selectionAndRefusalAreVisible() {
        Arena a = arena();
        ViewTransform v = view(a);
        BufferedImage plain = render(a, null, ArenaRenderer.Overlay.NONE);
        BufferedImage selected = render(a, null, new ArenaRenderer.Overlay(Set.of(new Item(Item.Kind.WALL, 0)), null, null, null));
        // The wall's end handle: a white square with a blue edge.
        assertEquals(Color.WHITE, at(selected, v, 200, 800));
        assertFalse(at(plain, v, 200, 800).equals(Color.WHITE));
        BufferedImage refused = render(a, null, new ArenaRenderer.Overlay(Set.of(), null, new double[] {500, 500, 40}, null));
        assertEquals(ArenaRenderer.REFUSED, at(refused, v, 540, 500), "a red ring where the placement was refused");
    }

    @Test
    void hitTestingFindsWhatIsDrawn() {
        Arena a = arena();
        assertEquals(new Item(Item.Kind.WALL, 0), ItemHits.hit(a, 500, 805, 2));
        assertEquals(new Item(Item.Kind.CAP, 0), ItemHits.hit(a, 205, 195, 2));
        assertEquals(new Item(Item.Kind.ROBOT, 0), ItemHits.hit(a, 510, 310, 2));
        assertNull(ItemHits.hit(a, 500, 600, 2));
        assertEquals(new ItemHits.Handle(new Item(Item.Kind.WALL, 0), 1),
                ItemHits.handleAt(a, Set.of(new Item(Item.Kind.WALL, 0)), 799, 801, 5));
    }

    @Test
    void sensorPanelDrawsBarsAndTheGripperState() {
        int[] prox = new int[8];
        prox[2] = 1023;
        RobotView r = new RobotView(0, "r", 1, 1, 0, 3, -3, 10, 20, Contact.NONE, prox, new int[8], 0, 0, "running",
                new GripperView(250, false, GripperState.CLOSED, true, 120, 0), 0);
        BufferedImage img = new BufferedImage(330, SensorRenderer.preferredHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        SensorRenderer.draw(g, 330, img.getHeight(), r);
        g.dispose();
        int red = count(img, SensorRenderer.PROX);
        assertTrue(red > 200, "a full proximity bar for sensor 2: " + red + " px");
        assertTrue(count(img, new Color(0xFF3030)) > 100, "the object sensor's LED is lit");
        BufferedImage none = new BufferedImage(330, SensorRenderer.preferredHeight(), BufferedImage.TYPE_INT_RGB);
        g = none.createGraphics();
        SensorRenderer.draw(g, 330, none.getHeight(), null);
        g.dispose();
        assertEquals(0, count(none, new Color(0xFF3030)), "no LED before a run");
    }

    /** The drawing grows with the panel, its text too: on a large screen it is not 10 px text in a corner. */
    @Test
    void theSensorPanelScalesWithItsSpaceTextIncluded() {
        int[] prox = new int[8];
        prox[2] = 1023;
        RobotView r = new RobotView(0, "r", 1, 1, 0, 3, -3, 10, 20, Contact.NONE, prox, new int[8], 0, 0, "running",
                new GripperView(250, false, GripperState.CLOSED, true, 120, 0), 0);
        int[] dark = new int[2];
        int[] red = new int[2];
        int[][] sizes = {{330, 410}, {660, 820}};
        for (int i = 0; i < 2; i++) {
            BufferedImage img = new BufferedImage(sizes[i][0], sizes[i][1], BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            SensorRenderer.draw(g, img.getWidth(), img.getHeight(), r);
            g.dispose();
            red[i] = count(img, SensorRenderer.PROX);
            dark[i] = countDark(img, 0, img.getWidth());
        }
        assertTrue(red[1] > 3.5 * red[0], "twice the size, four times the bar: " + red[0] + " -> " + red[1] + " px");
        assertTrue(dark[1] > 3 * dark[0], "twice the size, text and lines four times the ink: " + dark[0] + " -> " + dark[1]);
        assertEquals(2.0, SensorRenderer.scale(660, 820), 1e-9);
        assertEquals(0.8, SensorRenderer.scale(400, 328), 1e-9, "a short panel scales down to its height");
    }

    @Test
    void aLampsGlowStaysOnTheFloor() {
        Arena a = new Arena("lit", 1000, 1000, List.of(new Pose(500, 300, 90)), List.of(),
                List.of(new org.kheperasim.sim.arena.Light(950, 500, 6, 600, 1, 0, 360)), List.of(), List.of());
        BufferedImage img = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        ViewTransform v = new ViewTransform();
        v.fit(a.width(), a.height(), SIZE, SIZE, 60);
        ArenaRenderer.draw(g, v, SIZE, SIZE, a, null, ArenaRenderer.Overlay.NONE, new ArenaRenderer.Options(false, false, false, false));
        g.dispose();
        assertEquals(ArenaRenderer.OUTSIDE, at(img, v, 1020, 500), "just outside the wall by the lamp: no glow");
        assertFalse(at(img, v, 900, 500).equals(ArenaRenderer.FLOOR), "inside, near the lamp, the floor glows");
    }

    /** The time axis' last label, at the right edge when the run is shorter than the span, is drawn whole, as are long values. */
    @Test
    void thePlotsLabelsStayInsideItAtShortSpans() {
        PlotCanvas c = new PlotCanvas();
        for (double to : new double[] {0.3, 1.2, 9.7, 612.35}) {
            double[][] data = {{0, to / 2, to}, {-1234567, 0, 2345678}};
            c.show(new PlotCanvas.Plot(data, new String[] {"encoder L"}, new int[] {0}, 0, to, Double.NaN,
                    "encoder, pulses (0.08 mm)", Double.NaN));
            BufferedImage img = new BufferedImage(300, 160, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            c.paintPlot(g, img.getWidth(), img.getHeight());
            g.dispose();
            assertEquals(0, countDark(img, img.getWidth() - 2, img.getWidth()), "nothing runs off the right edge, span to " + to);
            assertEquals(0, countDark(img, 0, 1), "nothing runs off the left edge, span to " + to);
        }
    }

    /** @return pixels darker than mid-grey in columns [x0, x1) */
    private static int countDark(BufferedImage img, int x0, int x1) {
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = x0; x < x1; x++) {
                Color c = new Color(img.getRGB(x, y));
                if (c.getRed() + c.getGreen() + c.getBlue() < 3 * 110) {
                    n++;
                }
            }
        }
        return n;
    }

    private static int count(BufferedImage img, Color c) {
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if (img.getRGB(x, y) == c.getRGB()) {
                    n++;
                }
            }
        }
        return n;
    }
}
