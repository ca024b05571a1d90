package org.kheperasim.sim.engine.model;

import java.util.LinkedHashMap;
import java.util.Map;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The {@code wsu} behaviour profile ({@code --set profile=wsu}): the original WSU Khepera
 * Simulator's behaviour for course code tuned on it. It is the bundled robot file {@code wsu}
 * (its proximity response and light levels) plus the settings here, which are not numbers of a
 * robot: no noise and no per-robot spread (its readings stand still and equal speeds drive
 * straight), its speed and position units, the lowered arm in the front sensors' view, and its
 * turret (exact levels, an image as often as its loop ran). A setting given explicitly wins over
 * the profile's. The default profile, {@code robot}, is the real robot and changes nothing.
 */
public final class WsuProfile {
    /** The profile setting's key. */
    public static final String KEY = "profile";
    /** Its value for the original simulator. */
    public static final String WSU = "wsu";

    private static final Map<String, String> SETTINGS = new LinkedHashMap<>();

    static {
        SETTINGS.put("noise.reading", "0");          // off: with its measured noise (wsu.yaml) two course pairings
                                                     // do otherwise than there (docs/wsu-migration.md)
        SETTINGS.put("vision.noise", "0");           // with noise.reading=1: exact turret levels, as there
        SETTINGS.put("motor.left.noise", "0");       // and no wheel noise: equal speeds keep the heading exactly
        SETTINGS.put("motor.right.noise", "0");
        SETTINGS.put("noise.robot", "0");            // no wheel spread: equal speeds keep the heading exactly
        SETTINGS.put("wsu.speedUnits", "legacy");    // as fast as the original drew it
        SETTINGS.put("wsu.positionUnits", "legacy"); // its counts, 3 per degree of a turn on the spot
        SETTINGS.put("gripper.armInView", "wsu");    // sensors 0-5 read the lowered arm
        SETTINGS.put("vision.lampGain", "0");        // exact levels: wall 10, ball 200, lamp 255
        SETTINGS.put("vision.refreshMs", "20");      // a new image for every loop (its loop ran every 23 ms)
        SETTINGS.put("vision.fieldOfViewDeg", "40"); // its image: a ball 174 mm ahead on 11 pixels, a lamp 16 degrees
        SETTINGS.put("vision.lensMm", "0");          // left centred on pixel 5.5 (taken from the robot's centre)
        SETTINGS.put("controller.mode", "onboard");  // values refresh at once, commands act at once, as there
        SETTINGS.put(LoopTiming.KEY, LoopTiming.DESKTOP); // its loop's pauses: 20 ms asked, sometimes far longer
    }

    private WsuProfile() {
    }

    /**
     * @param profile a {@code profile} value
     * @param key a setting's key
     * @return the profile's value for it, or null when the profile leaves it at the default
     */
    static String setting(String profile, String key) {
        return WSU.equals(profile) ? SETTINGS.get(key) : null;
    }

    /** @return the settings the {@code wsu} profile changes, in a stable order */
    public static Map<String, String> settings() {
        return java.util.Collections.unmodifiableMap(SETTINGS);
    }

    /**
     * @param settings a robot's settings
     * @param type the type its arena line names
     * @return the {@code wsu} robot when the settings choose the profile and the line names the default robot
     */
    public static RobotType robotFor(Settings settings, RobotType type) {
        return WSU.equals(settings.raw(KEY)) && type == RobotTypes.KHEPERA1 ? RobotTypes.WSU : type;
    }

    /**
     * @param settings a robot's settings
     * @param type its type
     * @return the settings with the profile chosen when the robot is a {@code wsu} (an arena's
     *     {@code robot ... wsu} line), else unchanged
     */
    public static Settings settingsFor(Settings settings, RobotType type) {
        return type == RobotTypes.WSU && !WSU.equals(settings.raw(KEY)) ? settings.with(KEY, WSU) : settings;
    }
}
