package org.kheperasim.sim.testkit;

/**
 * A named rectangle of an arena's floor.
 *
 * @param name its name
 * @param x1 left edge, mm
 * @param y1 bottom edge, mm
 * @param x2 right edge, mm
 * @param y2 top edge, mm
 */
public record KitRegion(String name, double x1, double y1, double x2, double y2) {
    /** @param x point, mm @param y point, mm @return true inside the rectangle or on its edge */
    public boolean contains(double x, double y) {
        return x >= x1 && x <= x2 && y >= y1 && y <= y2;
    }
}
