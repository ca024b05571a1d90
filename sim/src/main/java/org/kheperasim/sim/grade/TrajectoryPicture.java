package org.kheperasim.sim.grade;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * Draws a run's trajectory from its trace into a PNG, headless: the arena (regions, walls, lamps),
 * each robot's path from its start (green) to its end (red), and the caps where they ended. Same
 * trace, same bytes; saved atomically (a grading killed while drawing leaves no half picture).
 */
final class TrajectoryPicture {
    private static final Color[] PATHS = {new Color(0x1f5fbf), new Color(0x9b30c0), new Color(0x0f8f6f),
            new Color(0xc06010)};

    private TrajectoryPicture() {
    }

    /**
     * @param arena   the arena the run was made in
     * @param trace   the run's trace
     * @param png     where the picture goes
     * @param maxSide the picture's longer side, pixels
     * @throws IOException if the trace cannot be read or the picture written
     */
    static void draw(Arena arena, Path trace, Path png, int maxSide) throws IOException {
        double scale = maxSide / StrictMath.max(arena.width(), arena.height());
        int w = (int) StrictMath.ceil(arena.width() * scale);
        int h = (int) StrictMath.ceil(arena.height() * scale);
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, w, h);
            // arena mm, y up -> pixels, y down
            g.transform(new AffineTransform(scale, 0, 0, -scale, 0, h));
            g.setColor(new Color(0xe8f0e0));
            for (Region r : arena.regions()) {
                g.fill(new Rectangle2D.Double(r.x1(), r.y1(), r.x2() - r.x1(), r.y2() - r.y1()));
            }
            g.setColor(new Color(0xc8d8b8));
            g.setStroke(new BasicStroke((float) (1 / scale)));
            for (Region r : arena.regions()) {
                g.draw(new Rectangle2D.Double(r.x1(), r.y1(), r.x2() - r.x1(), r.y2() - r.y1()));
            }
            g.setColor(new Color(0x404040));
            for (Wall wall : arena.walls()) {
                g.setStroke(new BasicStroke((float) StrictMath.max(wall.thickness(), 1 / scale), BasicStroke.CAP_ROUND,
                        BasicStroke.JOIN_ROUND));
                g.draw(new Line2D.Double(wall.x1(), wall.y1(), wall.x2(), wall.y2()));
            }
            g.setColor(new Color(0xf0c000));
            for (Light l : arena.lights()) {
                double r = StrictMath.max(l.radius(), 3 / scale);
                g.fill(new Ellipse2D.Double(l.x() - r, l.y() - r, 2 * r, 2 * r));
            }
            paths(g, arena, trace, scale);
        } finally {
            g.dispose();
        }
        Files.createDirectories(png.toAbsolutePath().getParent());
        AtomicFiles.writePng(png, img);
    }

    private static void paths(Graphics2D g, Arena arena, Path trace, double scale) throws IOException {
        Map<Integer, Path2D.Double> paths = new TreeMap<>();
        Map<Integer, double[]> caps = new HashMap<>();
        try (BufferedReader in = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
            String line;
            while ((line = in.readLine()) != null) {
                if (line.isEmpty() || line.charAt(0) == '#') {
                    continue;
                }
                String[] t = line.split(" ", 6);
                if (t.length < 5) {
                    continue;
                }
                try {
                    if (t[1].equals("cap")) {
                        caps.put(Integer.parseInt(t[2]),
                                new double[] {Double.parseDouble(t[3]), Double.parseDouble(t[4])});
                    } else {
                        double x = Double.parseDouble(t[2]);
                        double y = Double.parseDouble(t[3]);
                        Path2D.Double p = paths.get(Integer.parseInt(t[1]));
                        if (p == null) {
                            p = new Path2D.Double();
                            p.moveTo(x, y);
                            paths.put(Integer.parseInt(t[1]), p);
                        } else {
                            p.lineTo(x, y);
                        }
                    }
                } catch (NumberFormatException e) {
                    // a line cut short by a killed run: skip it
                }
            }
        }
        double capR = 4 / scale;
        g.setColor(new Color(0xe07020));
        for (int i = 0; i < arena.caps().size(); i++) {
            Cap c = arena.caps().get(i);
            double[] at = caps.getOrDefault(i, new double[] {c.x(), c.y()});
            g.fill(new Ellipse2D.Double(at[0] - capR, at[1] - capR, 2 * capR, 2 * capR));
        }
        g.setStroke(new BasicStroke((float) (1.5 / scale), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        double dot = 4 / scale;
        for (Map.Entry<Integer, Path2D.Double> e : paths.entrySet()) {
            Path2D.Double p = e.getValue();
            g.setColor(PATHS[e.getKey() % PATHS.length]);
            g.draw(p);
            double[] first = new double[2];
            double[] last = new double[2];
            endpoints(p, first, last);
            g.setColor(new Color(0x20a020));
            g.fill(new Ellipse2D.Double(first[0] - dot, first[1] - dot, 2 * dot, 2 * dot));
            g.setColor(new Color(0xd02020));
            g.fill(new Ellipse2D.Double(last[0] - dot, last[1] - dot, 2 * dot, 2 * dot));
        }
    }

    private static void endpoints(Path2D.Double p, double[] first, double[] last) {
        double[] c = new double[6];
        boolean seen = false;
        for (java.awt.geom.PathIterator it = p.getPathIterator(null); !it.isDone(); it.next()) {
            it.currentSegment(c);
            if (!seen) {
                first[0] = c[0];
                first[1] = c[1];
                seen = true;
            }
            last[0] = c[0];
            last[1] = c[1];
        }
    }
}
