package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.engine.space.ArcTrig;

/**
 * Where a glide of some ticks from the body's pose would end, without moving it: the engine samples
 * sensors inside a glide this way. The arithmetic is the glide's own ({@link DriveBody#glide}).
 */
public final class GlidePreview {
    private final DriveBody body;

    GlidePreview(DriveBody body) {
        this.body = body;
    }

    /**
     * The position and counters {x, y, -, -, left encoder, right encoder} after a glide of {@code ticks}
     * ticks into {@code out} (the heading is {@link #heading}'s).
     */
    public void position(long ticks, double[] out) {
        counters(ticks, out);
        if (ticks == 0 || body.wheels().still()) {
            out[0] = body.x();
            out[1] = body.y();
            return;
        }
        double common = body.halfArcOf(ticks);
        ArcTrig trig = body.arcTrig();
        double c = body.cos();
        double s = body.sin();
        out[0] = body.x() + common * trig.chord * (c * trig.halfCos - s * trig.halfSin);
        out[1] = body.y() + common * trig.chord * (s * trig.halfCos + c * trig.halfSin);
    }

    /** The heading at the end of a glide of {@code ticks} ticks, {cos, sin} into {@code out[2, 3]}. */
    public void heading(long ticks, double[] out) {
        double c = body.cos();
        double s = body.sin();
        if (ticks == 0 || body.wheels().still()) {
            out[2] = c;
            out[3] = s;
            return;
        }
        ArcTrig trig = body.arcTrig();
        trig.full(body.wheels().turn(ticks));
        double tc = c * trig.fullCos - s * trig.fullSin;
        double ts = s * trig.fullCos + c * trig.fullSin;
        double n = 1.0 / StrictMath.sqrt(tc * tc + ts * ts);
        out[2] = tc * n;
        out[3] = ts * n;
    }

    /** The counters of {@link #position} ({@code out[4, 5]}), without the arc's trigonometry. */
    public void counters(long ticks, double[] out) {
        Wheels wheels = body.wheels();
        if (ticks == 0 || wheels.still()) {
            body.odometry().preview(0, 0, out);
            return;
        }
        body.odometry().preview(wheels.common(ticks), wheels.diff(ticks), out);
    }
}
