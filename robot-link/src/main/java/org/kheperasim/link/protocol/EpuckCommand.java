package org.kheperasim.link.protocol;

import java.util.List;

/**
 * The e-puck's own commands of its ASCII protocol (GCtronic's SerCom/asercom, as its firmware
 * answers them; see docs/protocol-server.md, "Dialects"): those whose letter, range or meaning
 * differ from the Khepera's. The letters the e-puck kept with the Khepera's meaning and reply
 * ({@code E}, {@code N}, {@code O}) are the Khepera's own records ({@link Command.ReadSpeed},
 * {@link Command.ReadProximity}, {@link Command.ReadLight}).
 *
 * <p>Values are the robot's counts, never converted: speeds in steps per second (±1000), the step
 * counters in motor steps (1000 steps a wheel turn).
 */
public sealed interface EpuckCommand extends Command {

    /** The fastest wheel speed the e-puck's motor library accepts, steps/s. */
    int MAX_SPEED = 1000;
    /** LED number that addresses all eight ring LEDs at once ({@code L,8,a}). */
    int ALL_LEDS = 8;

    private static int check(String command, String what, int value, int min, int max) {
        if (value < min || value > max) {
            throw new IllegalArgumentException(command + ": " + what + " " + value + " is outside " + min + ".." + max);
        }
        return value;
    }

    /** {@code D,l,r}: wheel speeds, steps/s, −1000..1000; reply {@code d}. */
    record SetSpeed(int left, int right) implements EpuckCommand {
        /** The stop command, {@code D,0,0}. */
        public static final SetSpeed STOP = new SetSpeed(0, 0);

        /** @param left left speed, steps/s @param right right speed, steps/s */
        public SetSpeed {
            check("D", "left speed", left, -MAX_SPEED, MAX_SPEED);
            check("D", "right speed", right, -MAX_SPEED, MAX_SPEED);
        }

        public char letter() { return 'D'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code L,n,a}: ring LED n (0..7, 8 = all) off (0), on (1) or inverted (2); reply {@code l}. */
    record SetLed(int led, int action) implements EpuckCommand {
        /** @param led 0..8 @param action 0 off, 1 on, 2 inverse */
        public SetLed {
            check("L", "LED", led, 0, ALL_LEDS);
            check("L", "action", action, 0, 2);
        }

        public char letter() { return 'L'; }
        public int[] args() { return new int[] {led, action}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code B,a}: the body LED off (0), on (1) or inverted (2); reply {@code b}. */
    record BodyLed(int action) implements EpuckCommand {
        /** @param action 0 off, 1 on, 2 inverse */
        public BodyLed {
            check("B", "action", action, 0, 2);
        }

        public char letter() { return 'B'; }
        public int[] args() { return new int[] {action}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code F,a}: the front LED off (0), on (1) or inverted (2); reply {@code f}. */
    record FrontLed(int action) implements EpuckCommand {
        /** @param action 0 off, 1 on, 2 inverse */
        public FrontLed {
            check("F", "action", action, 0, 2);
        }

        public char letter() { return 'F'; }
        public int[] args() { return new int[] {action}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code P,l,r}: set the two step counters; reply {@code p}. */
    record SetSteps(int left, int right) implements EpuckCommand {
        public char letter() { return 'P'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code Q}: read the two step counters; reply {@code q,l,r}, steps. */
    record ReadSteps() implements EpuckCommand {
        public char letter() { return 'Q'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 2; }
    }

    /** {@code S}: stop the wheels and turn the LEDs off; reply {@code s}. */
    record Stop() implements EpuckCommand {
        public char letter() { return 'S'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 0; }
    }

    /** {@code R}: reset; reply {@code r}, then the robot restarts and prints its welcome banner. */
    record Reset() implements EpuckCommand {
        public char letter() { return 'R'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 0; }
    }

    /** {@code V}: the firmware's version; reply {@code v,<text>}, e.g. {@code v,Version 1.1.3 September 2006}. */
    record Version() implements EpuckCommand {
        public char letter() { return 'V'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 1; }
        public boolean integerReply() { return false; }

        /** @param text the version text @return the reply */
        public Reply reply(String text) {
            return new Reply(this, List.of(text));
        }
    }

    /**
     * {@code H}: help. The reply is not one line: an empty line, then one line per command
     * ({@code "D,#,#"   Set motor speed left,right}); no reply letter, so a client reads it as text.
     */
    record Help() implements EpuckCommand {
        public char letter() { return 'H'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return -1; }
    }
}
