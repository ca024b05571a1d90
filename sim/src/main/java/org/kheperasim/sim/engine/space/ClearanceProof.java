package org.kheperasim.sim.engine.space;

/**
 * A lower bound of the distance field's clearance looked up at one point and carried along: the
 * clearance changes no faster than the point moves, so at a point {@code d} away it is at least the
 * bound less {@code d}. Asking costs no look-up (no memory touched beyond this object).
 */
public final class ClearanceProof {
    private double x;
    private double y;
    private double below = Double.NEGATIVE_INFINITY;

    /** The field's lower bound of the clearance at (px, py) is {@code clearanceBelow}, mm. */
    public void set(double px, double py, double clearanceBelow) {
        x = px;
        y = py;
        below = clearanceBelow;
    }

    /** Forget the bound (the arena was edited). */
    public void forget() {
        below = Double.NEGATIVE_INFINITY;
    }

    /** @return a lower bound of the clearance at (px, py), from the kept bound alone, mm */
    public double at(double px, double py) {
        double mx = px - x;
        double my = py - y;
        return below - StrictMath.sqrt(mx * mx + my * my);
    }

    /** @return true when the kept bound alone proves the disc of radius {@code r} around (px, py) free */
    public boolean proves(double px, double py, double r) {
        double slack = below - r;
        double mx = px - x;
        double my = py - y;
        return slack > 0 && mx * mx + my * my < slack * slack;
    }
}
