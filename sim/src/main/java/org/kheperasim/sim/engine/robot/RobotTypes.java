package org.kheperasim.sim.engine.robot;

import java.util.List;
import java.util.Set;

/** The bundled robot types; {@link #KHEPERA1}, the paper's robot, is the default. */
public final class RobotTypes {
    /**
     * The Khepera I's proximity response against a white wall (khepera-reference.md, "Default sensor
     * profile"): about 1000 within a few mm, 600 at 20 mm (the Appendix controller's threshold),
     * nothing by 60 mm; the sensor's offset puts a noise floor of a few tens beyond 50 mm.
     */
    private static final ProximityProfile KHEPERA1_CURVE = new ProximityProfile("khepera1",
            new double[] {0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60},
            new double[] {1023, 985, 880, 745, 600, 455, 325, 215, 130, 70, 30, 10, 0});

    /**
     * The Khepera II white-sheet calibration (RoadNarrows' default, taken "placing a sheet of white
     * paper at various distances", Khepera manual section 3.1.8): 1000 at 10 mm, 450 at 20 mm, 80 at
     * 100 mm. Those are whole readings, the sensor's residual included, so the table holds them less
     * the nominal offset (15) that every reading adds: a robot's mean reading at each distance is the
     * published one. Beyond 100 mm the response falls to nothing by 120 mm.
     */
    private static final ProximityProfile KHEPERA2_CURVE = new ProximityProfile("khepera2",
            new double[] {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 120},
            new double[] {1008, 985, 435, 260, 175, 135, 110, 95, 85, 75, 65, 0});

    /** The IR cone: the axis, and pairs at 12 and 24 degrees weighted 0.85 and 0.5. */
    private static final double[] CONE_DEG = {0, 12, 24};
    private static final double[] CONE_WEIGHTS = {1.0, 0.85, 0.5};

    /** The Khepera I of the paper (khepera-reference.md, "Units and geometry"). */
    public static final RobotType KHEPERA1 = new RobotType("khepera1",
            "K-Team Khepera User Manual v5.02 (1999); sensor poses: Player's Khepera defaults",
            new RobotType.Body(27.5),
            new RobotType.Drive(53.0, 8.0, 127, 0.08, 10_000_000L, 50_000_000L, 20, 64),
            List.of(new RobotType.Sensor("LEFT_90", 0, 10, 24, 90), new RobotType.Sensor("LEFT_45", 1, 19, 17, 45),
                    new RobotType.Sensor("FRONT_LEFT", 2, 25, 6, 0), new RobotType.Sensor("FRONT_RIGHT", 3, 25, -6, 0),
                    new RobotType.Sensor("RIGHT_45", 4, 19, -17, -45), new RobotType.Sensor("RIGHT_90", 5, 10, -24, -90),
                    new RobotType.Sensor("BACK_RIGHT", 6, -24, -10, 180), new RobotType.Sensor("BACK_LEFT", 7, -24, 10, 180)),
            new RobotType.Proximity(new Response.Curve(KHEPERA1_CURVE, CONE_DEG, CONE_WEIGHTS), 15, 3, 0.03, 1023),
            new RobotType.Light(480, 20, 0.01),
            Set.of(RobotType.Turret.GRIPPER, RobotType.Turret.VISION), "khepera1");

    /** The built-in proximity responses that {@code prox.profile} names. */
    private static final List<ProximityProfile> PROFILES = List.of(KHEPERA1_CURVE, KHEPERA2_CURVE);

    private RobotTypes() {
    }

    /**
     * @param name {@code khepera1}, {@code khepera2}, or {@code sample:PATH} (a table fitted to a
     *     sampled wall file, {@link SampleResponses})
     * @return that robot's proximity response, for the {@code prox.profile} setting
     */
    public static Response profile(String name) {
        if (name.startsWith(SampleResponses.PREFIX)) {
            return SampleResponses.fit(name.substring(SampleResponses.PREFIX.length()), KHEPERA1).table();
        }
        for (ProximityProfile p : PROFILES) {
            if (p.name().equals(name)) {
                return new Response.Curve(p, CONE_DEG, CONE_WEIGHTS);
            }
        }
        throw new IllegalArgumentException("unknown proximity profile '" + name + "'; use one of "
                + PROFILES.stream().map(ProximityProfile::name).toList() + " or sample:PATH");
    }
}
