package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.engine.view.Contact;

/**
 * What the body touches after its last move: nothing, or a point (of a wall, a robot, a cap). The side
 * is worked out when asked for, from the pose the body has then (it keeps it until its next move,
 * which sets the touch anew), since most contacts are never looked at.
 */
final class Touch {
    /** The side of the present contact; null while it is still to be worked out from the point. */
    private Contact side = Contact.NONE;
    private double x;
    private double y;

    /** The body touches something at (ox, oy). */
    void at(double ox, double oy) {
        side = null;
        x = ox;
        y = oy;
    }

    /** The body touches nothing. */
    void none() {
        side = Contact.NONE;
    }

    /** @return the side the body, at (px, py) heading (cos, sin), touches on */
    Contact side(double px, double py, double cos, double sin) {
        if (side == null) {
            side = Contact.ofAngle(StrictMath.atan2(y - py, x - px) - StrictMath.atan2(sin, cos));
        }
        return side;
    }

    /** @return the point touched, {x, y} mm (the last one; meaningful while the side is not NONE) */
    double[] point() {
        return new double[] {x, y};
    }
}
