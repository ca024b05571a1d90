package org.kheperasim.sim.engine;

/**
 * What a robot may do to the caps, or see of them, during a stretch of ticks: whether it may move a
 * cap (push, carry, grab or drop one) and whether a cap that others move may come within its
 * sensors' reach. {@link Motion} steps the robots concerned tick by tick, so that every sample sees
 * the caps where they are at its tick.
 */
final class CapsInReach {
    private final DriveBody body;
    private final GripperModel gripper;
    private final CapContacts contacts;
    private final boolean ticking;
    private final double unseenMm;

    /**
     * @param ticking the robot steps every tick (the reference): it is taken to move caps always
     * @param unseenMm a cap's surface farther than this from the centre is out of every sensor's reach, mm
     */
    CapsInReach(DriveBody body, GripperModel gripper, CapContacts contacts, boolean ticking, double unseenMm) {
        this.body = body;
        this.gripper = gripper;
        this.contacts = contacts;
        this.ticking = ticking;
        this.unseenMm = unseenMm;
    }

    /**
     * @param ticks a stretch's length
     * @return how far a cap the robot pushes or carries may move during the stretch at most, mm; 0
     *     when its gripper is still and empty and no cap is within its parts' reach throughout
     */
    double driftMm(long ticks) {
        boolean apart = !ticking && !gripper.busy() && gripper.heldCap() < 0
                && contacts.freeTravelMm(body.x(), body.y()) > body.travelPerTickMm() * ticks + 1e-6;
        if (apart) {
            return 0;
        }
        // A cap pushed or carried moves no farther than the part that moves it (twice that, to be safe).
        return 2 * body.partTravelPerTickMm(StrictMath.max(GripperTurret.REACH_MM, Khepera.BODY_RADIUS_MM)) * ticks + 1e-6;
    }

    /**
     * @param ticks a stretch's length
     * @param drift how far a cap may be moved by others meanwhile, mm
     * @return true when a cap may come within reach of the robot's sensors or parts during the stretch
     */
    boolean watched(long ticks, double drift) {
        return contacts.nearestCapMm(body.x(), body.y()) <= unseenMm + body.travelPerTickMm() * ticks + drift + 1e-6;
    }
}
