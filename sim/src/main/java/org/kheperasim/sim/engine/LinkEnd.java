package org.kheperasim.sim.engine;

import org.kheperasim.api.GripperState;

/**
 * The robot's end of its simulated serial link: what a command that has arrived does to the parts
 * (wheels, counters, arm, fingers) and how a poll sample is taken from them (proximity, light,
 * counters), at the pose {@link SamplePose} gives for the sample's tick. Each sensor's samples are
 * numbered, and the number keys its noise draws.
 */
final class LinkEnd implements RobotLink.Robot {
    private final DriveBody body;
    private final SamplePose sense;
    private final ProximitySensing proximity;
    private final LightSensing light;
    private final GripperModel gripper;
    private final Coverage coverage;
    private long proximitySamples;
    private long lightSamples;

    LinkEnd(DriveBody body, SamplePose sense, ProximitySensing proximity, LightSensing light, GripperModel gripper,
            Coverage coverage) {
        this.body = body;
        this.sense = sense;
        this.proximity = proximity;
        this.light = light;
        this.gripper = gripper;
        this.coverage = coverage;
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
    public void sampleProximity(int[] out) {
        double[] at = sense.position();
        if (proximity.open(at[0], at[1])) {
            proximity.sampleOpen(proximitySamples++, out);
        } else {
            at = sense.pose();
            proximity.sampleNear(at[0], at[1], at[2], at[3], proximitySamples++, out);
        }
        coverage.mark(at[0], at[1]);
    }

    @Override
    public void sampleLight(int[] out) {
        double[] at = sense.pose();
        light.sample(at[0], at[1], at[2], at[3], lightSamples++, out);
    }

    @Override
    public long pollLight(int[] out) {
        if (light.deferDark() >= 0) {
            return lightSamples++;
        }
        sampleLight(out);
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
