package org.kheperasim.sim.engine.sensing;

import java.util.List;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.RayHit;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.model.VisionModel;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.space.Bodies;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.DriverRecorder;
import org.kheperasim.sim.engine.view.VisionView;

/**
 * The K213 linear vision turret of one robot (the numbers are in {@link VisionModel}): a row of 64
 * pixels across 36° straight ahead. Each pixel's ray is cast from the lens over the occupancy grid
 * to the first wall, lamp or cap it meets (or another robot's body), and sees that surface's grey
 * level in the room's light, brightened by the lamps that light it (the light sensors' exposure
 * model, shadows included); a lamp itself saturates at 255. Then a per-pixel noise, and the value is
 * rounded to one of the 256 grey levels.
 *
 * <p>The room's light is even, and the turret's light detector adapts the exposure to it (the
 * manual's "iris"), so a surface's grey level does not depend on its distance: a white ball reads
 * about the same at 5 cm as at 50 cm, and a wall is dark wherever it is.
 *
 * <p><b>Time.</b> The turret takes an image every {@code vision.refreshMs}; reading it gives the
 * image of the present period. An image is computed only when somebody reads it, at the first read
 * in its period, from the robot where it is then; its noise is draw {@code 64 k + i} of the
 * turret's own stream for pixel {@code i} of period {@code k}, so reading or not never shifts another
 * draw, and a run that never reads the turret computes nothing. Taking an image moves nothing (the
 * robots stand where the tick began), but the image is shown in the trace (its vision line), so each
 * image taken is told to the engine's {@link DriverRecorder}: the command log's open-loop replay, which
 * runs no controller, takes the same images at the same moments.
 */
public final class LinearCamera {
    /** A lamp's signal: far above what the sensor can count, so it reads 255 whatever the noise. */
    private static final double LAMP_SIGNAL = 4.0 * VisionModel.MAX_GREY;

    private final World world;
    private final int self;
    private final DriveBody body;
    private final VisionModel model;
    private final CounterNoise noise;
    private final RayHit hit = new RayHit();
    private final double[] bearingCos = new double[VisionModel.PIXELS];
    private final double[] bearingSin = new double[VisionModel.PIXELS];
    private final int[] image = new int[VisionModel.PIXELS];
    private long period = -1;
    private VisionView last;
    /** Hears each image taken (a command log), or null. */
    private DriverRecorder recorder;

    public LinearCamera(World world, int self, DriveBody body, VisionModel model, CounterNoise noise) {
        this.world = world;
        this.self = self;
        this.body = body;
        this.model = model;
        this.noise = noise;
        for (int i = 0; i < VisionModel.PIXELS; i++) {
            double b = model.bearing(i);
            bearingCos[i] = StrictMath.cos(b);
            bearingSin[i] = StrictMath.sin(b);
        }
    }

    /**
     * @param now simulated time, ns; the robot has been moved to it
     * @return a new copy of the image of the present period: 64 grey levels, 0..255, index 0 the leftmost
     */
    public int[] image(long now) {
        return take(now).clone();
    }

    /**
     * @param now simulated time, ns @return the index of the brightest pixel of the present image, the leftmost of
     *     equals
     */
    public int brightest(long now) {
        int[] img = take(now);
        int best = 0;
        for (int i = 1; i < img.length; i++) {
            if (img[i] > img[best]) {
                best = i;
            }
        }
        return best;
    }

    /**
     * @param now simulated time, ns @return the index of the darkest pixel of the present image, the leftmost of equals
     */
    public int darkest(long now) {
        int[] img = take(now);
        int best = 0;
        for (int i = 1; i < img.length; i++) {
            if (img[i] < img[best]) {
                best = i;
            }
        }
        return best;
    }

    /**
     * @param recorder hears each image the turret takes from now on (see
     *     {@link org.kheperasim.sim.engine.Engine#record})
     */
    public void record(DriverRecorder recorder) {
        this.recorder = recorder;
    }

    /** @return the image last taken, or null when the turret has not been read */
    public VisionView lastView() {
        return last;
    }

    private int[] take(long now) {
        long k = now / model.refreshNanos();
        if (k != period) {
            if (recorder != null) {
                // What the image shows reaches the trace: a replay of the run must take it at the same moment.
                recorder.image(self, now);
            }
            period = k;
            render(k);
            last = new VisionView(self, now, image);
        }
        return image;
    }

    private void render(long k) {
        OccupancyGrid grid = world.grid();
        double c = body.cos();
        double s = body.sin();
        double lx = body.x() + c * model.lensMm();
        double ly = body.y() + s * model.lensMm();
        double reach = StrictMath.hypot(world.arena().width(), world.arena().height()) + 1;
        for (int i = 0; i < VisionModel.PIXELS; i++) {
            double dx = c * bearingCos[i] - s * bearingSin[i];
            double dy = s * bearingCos[i] + c * bearingSin[i];
            double d = grid.castRay(lx, ly, dx, dy, reach, hit);
            int id = d == Double.POSITIVE_INFINITY ? OccupancyGrid.FLOOR : hit.id;
            double signal;
            double robot = nearestRobot(lx, ly, dx, dy);
            if (robot < d) {
                signal = model.robotGrey() * lit(lx + (robot - 1) * dx, ly + (robot - 1) * dy);
            } else if (id == OccupancyGrid.LIGHT) {
                signal = LAMP_SIGNAL;
            } else if (id == OccupancyGrid.WALL) {
                signal = model.wallGrey() * lit(lx + (d - 1) * dx, ly + (d - 1) * dy);
            } else if (id >= OccupancyGrid.FIRST_CAP) {
                signal = model.capGrey() * lit(lx + (d - 1) * dx, ly + (d - 1) * dy);
            } else {
                signal = model.backgroundGrey();
            }
            if (model.noise() > 0) {
                signal += noise.gaussian(k * VisionModel.PIXELS + i) * model.noise();
            }
            image[i] = (int) StrictMath.max(0, StrictMath.min(VisionModel.MAX_GREY, StrictMath.rint(signal)));
        }
    }

    /** @return how much brighter than the room's light a surface point at (px, py) is, 1 or more */
    private double lit(double px, double py) {
        if (model.lampGain() == 0) {
            return 1;
        }
        double exposure = 0;
        List<Light> lights = world.arena().lights();
        for (int j = 0; j < lights.size(); j++) {
            Light light = lights.get(j);
            double r = StrictMath.hypot(light.x() - px, light.y() - py);
            if (r >= light.range() || !light.shinesOn(px, py)
                    || !world.grid().lightReaches(px, py, light.x(), light.y())) {
                continue;
            }
            double falloff = 1 - r / light.range();
            exposure += light.intensity() * falloff * falloff;
        }
        return 1 + model.lampGain() * StrictMath.min(1, exposure);
    }

    /** @return the distance along the ray to the nearest other robot's body, or infinity */
    private double nearestRobot(double px, double py, double dx, double dy) {
        Bodies bodies = world.bodies();
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < bodies.count(); j++) {
            if (j == self) {
                continue;
            }
            double r = bodies.radius(j);
            double ox = bodies.x(j) - px;
            double oy = bodies.y(j) - py;
            double along = ox * dx + oy * dy;
            double across2 = ox * ox + oy * oy - along * along;
            if (along <= 0 || across2 > r * r) {
                continue;
            }
            double t = along - StrictMath.sqrt(r * r - across2);
            if (t > 0 && t < best) {
                best = t;
            }
        }
        return best;
    }
}
