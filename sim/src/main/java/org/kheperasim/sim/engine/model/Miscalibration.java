package org.kheperasim.sim.engine.model;

import org.kheperasim.sim.engine.noise.CounterNoise;

/**
 * A robot's systematic errors, drawn once per run from its own stream (the paper's per-robot
 * degradation, like a worn motor): each proximity sensor's gain and offset, each light sensor's
 * darkness value, each wheel's calibration. The draws are made whatever the settings, at fixed
 * indices, so changing one setting never shifts another's draw.
 */
public final class Miscalibration {
    public final double[] proxGain;
    public final double[] proxOffset;
    public final double[] lightDark;
    public final double calibrationLeft;
    public final double calibrationRight;

    public Miscalibration(RobotModel model, CounterNoise systematic) {
        double scale = model.noise().robot();
        RobotModel.Proximity p = model.proximity();
        RobotModel.Light l = model.light();
        int n = model.type().sensorCount();
        proxGain = new double[n];
        proxOffset = new double[n];
        lightDark = new double[n];
        for (int i = 0; i < n; i++) {
            double g = systematic.gaussian(3L * i);
            double o = systematic.uniform(3L * i + 1) * 2 - 1;
            double d = systematic.gaussian(3L * i + 2);
            proxGain[i] = p.gain()[i] * (1 + p.gainSpread() * scale * g);
            proxOffset[i] = p.offset() + p.offsetSpread() * scale * o;
            lightDark[i] = l.dark() + l.darkSpread() * scale * d;
        }
        double spread = model.motors().spread() * scale;
        calibrationLeft = model.motors().calibrationLeft() * (1 + spread * systematic.gaussian(100));
        calibrationRight = model.motors().calibrationRight() * (1 + spread * systematic.gaussian(101));
    }
}
