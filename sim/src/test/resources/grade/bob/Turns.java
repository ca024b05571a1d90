/** Bob's helper: which way to turn for the two front sensors. */
final class Turns {
    private Turns() {
    }

    static int[] away(int frontLeft, int frontRight) {
        if (frontLeft > 400 || frontRight > 400) {
            return frontLeft > frontRight ? new int[] {3, -3} : new int[] {-3, 3};
        }
        return new int[] {4, 4};
    }
}
