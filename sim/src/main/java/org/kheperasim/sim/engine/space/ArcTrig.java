package org.kheperasim.sim.engine.space;

/**
 * The trigonometry of a robot's arc, for a turn (rad) over a move: the half turn's sine and cosine
 * and the chord factor place the centre, the whole turn's turn the heading. Each half is kept for
 * the last turn it was asked for, since a robot's turn per move often repeats, and a sample's
 * position may be wanted without its heading.
 */
public final class ArcTrig {
    private double halfTurn = Double.NaN;
    private double fullTurn = Double.NaN;
    public double halfCos = 1;
    public double halfSin;
    /** The chord's length over the arc's: sin(turn / 2) / (turn / 2), 1 for no turn. */
    public double chord = 1;
    public double fullCos = 1;
    public double fullSin;

    /** Set the half turn's values for {@code turn}. */
    public void half(double turn) {
        if (turn != halfTurn) {
            halfTurn = turn;
            halfCos = cosOf(turn * 0.5);
            halfSin = sinOf(turn * 0.5);
            chord = turn == 0 ? 1 : halfSin / (turn * 0.5);
        }
    }

    /** Set the whole turn's values for {@code turn}. */
    public void full(double turn) {
        if (turn != fullTurn) {
            fullTurn = turn;
            fullCos = cosOf(turn);
            fullSin = sinOf(turn);
        }
    }

    /** @return the turn {@link #half} was last set for */
    public double turn() {
        return halfTurn;
    }

    /** sin of a turn: a Taylor series exact to double precision for |a| ≤ 0.1, else {@link StrictMath}. */
    static double sinOf(double a) {
        if (StrictMath.abs(a) > 0.1) {
            return StrictMath.sin(a);
        }
        double a2 = a * a;
        return a * (1 - a2 / 6 * (1 - a2 / 20 * (1 - a2 / 42 * (1 - a2 / 72))));
    }

    /** cos of a turn; see {@link #sinOf}. */
    static double cosOf(double a) {
        if (StrictMath.abs(a) > 0.1) {
            return StrictMath.cos(a);
        }
        double a2 = a * a;
        return 1 - a2 / 2 * (1 - a2 / 12 * (1 - a2 / 30 * (1 - a2 / 56 * (1 - a2 / 90))));
    }
}
