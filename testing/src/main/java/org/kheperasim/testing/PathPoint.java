package org.kheperasim.testing;

/**
 * One sample of a robot's path: where it was at a sample time of the run (every 50 ms of simulated time
 * unless {@link RunBuilder#sampleEvery} says otherwise), as the run's trace records it.
 *
 * @param time simulated time of the sample
 * @param x centre of the robot, mm
 * @param y centre of the robot, mm
 * @param headingDeg heading, degrees counter-clockwise from +x
 */
public record PathPoint(SimTime time, double x, double y, double headingDeg) {

    /** @return the pose at this sample */
    public Pose pose() {
        return new Pose(x, y, headingDeg);
    }
}
