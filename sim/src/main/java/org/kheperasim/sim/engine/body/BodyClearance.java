package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.engine.space.ClearanceProof;

/**
 * The clearance of a robot's body from walls and lamps (from the distance field): the value where
 * the body is, kept between moves and after a glide computed only when first needed, and cheap
 * lower bounds of how far the centre can travel without a contact, so the exact value is looked up
 * only when a bound would cut a glide short.
 */
final class BodyClearance {
    private final DistanceField field;
    /** The body's radius, mm. */
    private final double radius;
    private double value;
    private boolean known;
    /** The field's lower bound of the clearance where it was last looked up. */
    private final ClearanceProof anchor = new ClearanceProof();

    BodyClearance(DistanceField field, double x, double y, double radius) {
        this.field = field;
        this.radius = radius;
        set(at(x, y));
    }

    /** @return the clearance of a centre at (px, py): the fast estimate, refined where contact is possible */
    double at(double px, double py) {
        double c = field.clearance(px, py);
        return c < radius + DriveBody.NEAR_MM ? field.preciseClearance(px, py) : c;
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
        return here(x, y) - DriveBody.NEAR_MM - radius - DriveBody.CONTACT_EPSILON_MM;
    }

    /**
     * @param lookUp false: only from the last look-up, less how far the body has moved since (no
     *     memory touched); true: look the field's bound up here too
     * @return a lower bound of {@link #freeTravel}, cheaper (a byte of the distance field at most):
     *     where it already allows what is asked, the exact value is not needed
     */
    double freeTravelAtLeast(double x, double y, boolean lookUp) {
        double below = anchor.at(x, y);
        if (lookUp) {
            double here = field.clearanceBelow(x, y);
            anchor.set(x, y, here);
            below = StrictMath.max(below, here);
        }
        return below - DriveBody.NEAR_MM - radius - DriveBody.CONTACT_EPSILON_MM;
    }

    /** The arena was edited: forget the bounds and look the clearance up again. */
    void arenaEdited(double x, double y) {
        anchor.forget();
        set(at(x, y));
    }
}
