package org.kheperasim.sim.engine;

import org.kheperasim.sim.arena.DistanceField;

/**
 * The clearance of a robot's body from walls and lamps (from the distance field): the value where
 * the body is, kept between moves and after a glide computed only when first needed, and cheap
 * lower bounds of how far the centre can travel without a contact, so the exact value is looked up
 * only when a bound would cut a glide short.
 */
final class BodyClearance {
    private final DistanceField field;
    private double value;
    private boolean known;
    /** Where the field's lower bound of the clearance was last looked up, and its value there (mm). */
    private double anchorX;
    private double anchorY;
    private double anchorBelow = Double.NEGATIVE_INFINITY;

    BodyClearance(DistanceField field, double x, double y) {
        this.field = field;
        set(at(x, y));
    }

    /** @return the clearance of a centre at (px, py): the fast estimate, refined where contact is possible */
    double at(double px, double py) {
        double c = field.clearance(px, py);
        return c < Khepera.BODY_RADIUS_MM + DriveBody.NEAR_MM ? field.preciseClearance(px, py) : c;
    }

    /** @return the clearance where the body is, (x, y) */
    double here(double x, double y) {
        if (!known) {
            set(at(x, y));
        }
        return value;
    }

    /** The body's clearance is now {@code c}. */
    void set(double c) {
        value = c;
        known = true;
    }

    /** The body glided: its clearance is computed when next needed. */
    void forget() {
        known = false;
    }

    /**
     * @return a lower bound of the distance from the centre at (x, y) to the nearest wall or lamp,
     *     less the body radius and the touching margin: the centre can travel that far without a contact, mm
     */
    double freeTravel(double x, double y) {
        // Both clearance estimates are upper bounds of the true clearance, within 2.2 cells of it.
        return here(x, y) - DriveBody.NEAR_MM - Khepera.BODY_RADIUS_MM - DriveBody.CONTACT_EPSILON_MM;
    }

    /**
     * @param lookUp false: only from the last look-up, less how far the body has moved since (no
     *     memory touched); true: look the field's bound up here too
     * @return a lower bound of {@link #freeTravel}, cheaper (a byte of the distance field at most):
     *     where it already allows what is asked, the exact value is not needed
     */
    double freeTravelAtLeast(double x, double y, boolean lookUp) {
        double mx = x - anchorX;
        double my = y - anchorY;
        // The clearance shrinks no faster than the body moves away from where it was last looked up.
        double below = anchorBelow - StrictMath.sqrt(mx * mx + my * my);
        if (lookUp) {
            anchorX = x;
            anchorY = y;
            anchorBelow = field.clearanceBelow(x, y);
            below = StrictMath.max(below, anchorBelow);
        }
        return below - DriveBody.NEAR_MM - Khepera.BODY_RADIUS_MM - DriveBody.CONTACT_EPSILON_MM;
    }

    /** The arena was edited: forget the bounds and look the clearance up again. */
    void arenaEdited(double x, double y) {
        anchorBelow = Double.NEGATIVE_INFINITY;
        set(at(x, y));
    }
}
