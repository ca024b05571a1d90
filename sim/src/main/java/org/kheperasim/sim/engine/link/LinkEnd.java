package org.kheperasim.sim.engine.link;

import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.sensing.LightSensing;
import org.kheperasim.sim.engine.sensing.SamplePose;
import org.kheperasim.sim.engine.sensing.Scans;

/**
 * The robot's end of its simulated serial link: what a command that has arrived does to the parts
 * (wheels, counters, arm, fingers), and what a poll reply carries: the proximity and light values of
 * the robot's latest {@link Scans scan}, and the counters where the robot is at the sample's tick
 * ({@link SamplePose}).
 */
public final class LinkEnd implements RobotLink.Robot {
    private final DriveBody body;
    private final SamplePose sense;
    private final GripperModel gripper;
    private final LightSensing light;
    private final Scans scans;

    public LinkEnd(DriveBody body, SamplePose sense, GripperModel gripper, LightSensing light, Scans scans) {
        this.body = body;
        this.sense = sense;
        this.gripper = gripper;
        this.light = light;
        this.scans = scans;
    }

    @Override
    public void applySpeeds(long now, int left, int right) {
        body.wheels().setSpeeds(left, right);
    }

    @Override
    public void applyCounters(int left, int right) {
        body.setCounters(left, right);
    }

    @Override
    public void applyArm(long now, int position) {
        gripper.moveArm(now, position);
    }

    @Override
    public void applyFingers(long now, boolean closed) {
        gripper.moveFingers(now, closed ? GripperState.CLOSED : GripperState.OPEN);
    }

    @Override
    public void sampleProximity(long now, int[] out) {
        scans.proximity(now, out);
    }

    @Override
    public void sampleLight(long now, int[] out) {
        scans.light(now, out);
    }

    @Override
    public long pollLight(long now, int[] out) {
        if (light.deferDark() >= 0) {
            return scans.indexAt(now);
        }
        scans.light(now, out);
        return -1;
    }

    @Override
    public int deferredLightChars() {
        return light.deferDark();
    }

    @Override
    public void fillLight(long key, int[] out) {
        light.fillDark(key, out);
    }

    @Override
    public int sampleCounterLeft() {
        return DriveBody.pulses(sense.counters()[4]);
    }

    @Override
    public int sampleCounterRight() {
        return DriveBody.pulses(sense.counters()[5]);
    }
}
