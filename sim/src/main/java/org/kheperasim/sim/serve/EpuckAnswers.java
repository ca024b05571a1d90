package org.kheperasim.sim.serve;

import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.dialect.EpuckDialect;
import org.kheperasim.sim.engine.SimRobot;

/**
 * What the served robot answers the e-puck's own commands ({@link EpuckCommand}), as GCtronic's
 * SerCom firmware does (docs/protocol-server.md, "Dialects"). The letters the e-puck shares with the
 * Khepera ({@code E}, {@code N}, {@code O}) are answered by {@link ServedRobot} as for the Khepera.
 * Values pass through unconverted: {@code D}'s steps/s go to the wheels as the robot type's counts.
 *
 * <p>LEDs: ring LED n is bit n of the robot's LED mask (8 = all eight), the body LED bit 8, the
 * front LED bit 9. Called holding the served arena's lock.
 */
final class EpuckAnswers {
    /** Bit of the LED mask that is the body LED. */
    static final int BODY_LED = 8;
    /** Bit of the LED mask that is the front LED. */
    static final int FRONT_LED = 9;

    /** The help text {@code H} answers: one line per command served, in the firmware's layout. */
    static final String HELP = String.join("\r\n",
            "",
            "\"B,#\"       Body led 0=off 1=on 2=inverse",
            "\"D,#,#\"     Set motor speed left,right",
            "\"E\"         Get motor speed left,right",
            "\"F,#\"       Front led 0=off 1=on 2=inverse",
            "\"H\"         Help",
            "\"L,#,#\"     Led number,0=off 1=on 2=inverse",
            "\"N\"         Proximity",
            "\"O\"         Light sensors",
            "\"P,#,#\"     Set motor position left,right",
            "\"Q\"         Get motor position left,right",
            "\"R\"         Reset e-puck",
            "\"S\"         Stop e-puck and turn off leds",
            "\"V\"         Version of SerCom");

    private EpuckAnswers() {
    }

    /**
     * @param robot the served robot
     * @param command an e-puck command
     * @return the reply, without its last line end (lines inside end in CR LF)
     */
    static String answer(SimRobot robot, EpuckCommand command) {
        if (command instanceof EpuckCommand.SetSpeed c) {
            robot.onBoard().driveSpeeds(c.left(), c.right());
        } else if (command instanceof EpuckCommand.SetLed c) {
            int first = c.led() == EpuckCommand.ALL_LEDS ? 0 : c.led();
            int last = c.led() == EpuckCommand.ALL_LEDS ? 7 : c.led();
            for (int led = first; led <= last; led++) {
                robot.onBoard().setLed(led, c.action());
            }
        } else if (command instanceof EpuckCommand.BodyLed c) {
            robot.onBoard().setLed(BODY_LED, c.action());
        } else if (command instanceof EpuckCommand.FrontLed c) {
            robot.onBoard().setLed(FRONT_LED, c.action());
        } else if (command instanceof EpuckCommand.SetSteps c) {
            robot.onBoard().setCounters(c.left(), c.right());
        } else if (command instanceof EpuckCommand.ReadSteps c) {
            return c.reply(robot.onBoard().counterLeft(), robot.onBoard().counterRight()).encode();
        } else if (command instanceof EpuckCommand.Stop) {
            robot.onBoard().driveSpeeds(0, 0);
            ledsOff(robot);
        } else if (command instanceof EpuckCommand.Reset c) {
            robot.emergencyStop();
            robot.onBoard().setCounters(0, 0);
            ledsOff(robot);
            String banner = EpuckDialect.BANNER;
            return c.reply().encode() + "\r\n" + banner.substring(0, banner.length() - 2);
        } else if (command instanceof EpuckCommand.Version c) {
            return c.reply(EpuckDialect.VERSION).encode();
        } else if (command instanceof EpuckCommand.Help) {
            return HELP;
        }
        return ((Command) command).reply().encode();
    }

    /** The firmware's {@code S} and reset turn every LED off. */
    private static void ledsOff(SimRobot robot) {
        for (int led = 0; led <= FRONT_LED; led++) {
            robot.onBoard().setLed(led, 0);
        }
    }
}
