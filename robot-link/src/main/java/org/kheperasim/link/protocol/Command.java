package org.kheperasim.link.protocol;

import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

/**
 * One command of the Khepera I/II protocol (Appendix A of the Khepera User Manual): an upper-case
 * letter and its decimal arguments. {@link #encode()} gives the line to send (without the line
 * terminator); {@link KheperaProtocol#parseCommand(String)} turns a received line back into the
 * typed command. Each command knows the head of its reply ({@code n}, or {@code t,1,g} for a turret
 * command) and how many values the reply carries.
 *
 * <p>The e-puck's commands that differ from these are {@link EpuckCommand}; a {@link
 * org.kheperasim.link.protocol.dialect.Dialect} says which commands a robot speaks.
 *
 * <p>Arguments are checked where the manual gives a range (speeds, PWM, LEDs, bytes); a value out
 * of range throws {@link IllegalArgumentException} naming the command, the value and the range.
 */
public sealed interface Command permits Command.SetSpeedPid, Command.ReadVersion, Command.MoveToPosition,
        Command.SetSpeed, Command.ReadSpeed, Command.SetPositionPid, Command.SetPositionCounters,
        Command.ReadPositionCounters, Command.ReadAnalog, Command.SetPositionProfile, Command.ReadMotionStatus,
        Command.SetLed, Command.ReadProximity, Command.ReadLight, Command.SetPwm, Command.ReadBus, Command.WriteBus,
        Command.Turret, EpuckCommand {

    /** @return the command letter, upper case */
    char letter();

    /** @return the decimal arguments after the letter, in order (none for a turret command) */
    int[] args();

    /** @return how many values the reply carries after its head; -1 when the protocol does not say */
    int replyValueCount();

    /** @return the reply's head: the lower-case letter, or {@code t,id,x} for a turret command */
    default String replyHead() {
        return String.valueOf(Character.toLowerCase(letter()));
    }

    /** @return whether the reply's values are decimal integers (false only for {@code b}'s version strings) */
    default boolean integerReply() {
        return true;
    }

    /** @return the command line, without a terminator, e.g. {@code D,3,-3} */
    default String encode() {
        StringBuilder b = new StringBuilder().append(letter());
        for (int a : args()) {
            b.append(',').append(a);
        }
        return b.toString();
    }

    /**
     * A reply to this command, as a robot or a simulator answering the protocol sends it.
     *
     * @param values the reply's values after its head
     * @return the reply
     */
    default Reply reply(int... values) {
        return new Reply(this, Arrays.stream(values).mapToObj(Integer::toString).collect(Collectors.toList()));
    }

    private static int check(String command, String what, int value, int min, int max) {
        if (value < min || value > max) {
            throw new IllegalArgumentException(command + ": " + what + " " + value + " is outside " + min + ".." + max);
        }
        return value;
    }

    /** {@code A,Kp,Ki,Kd}: the speed controller's PID gains (reset defaults 3800, 800, 100). */
    record SetSpeedPid(int kp, int ki, int kd) implements Command {
        public char letter() { return 'A'; }
        public int[] args() { return new int[] {kp, ki, kd}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code B}: read the BIOS and protocol versions; reply {@code b,5.02,5.01}. */
    record ReadVersion() implements Command {
        public char letter() { return 'B'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 2; }
        public boolean integerReply() { return false; }

        /** @param bios BIOS version, e.g. 5.02 @param protocol protocol version @return the reply */
        public Reply reply(String bios, String protocol) {
            return new Reply(this, List.of(bios, protocol));
        }
    }

    /** {@code C,l,r}: move the wheels to absolute position-counter targets, pulses. */
    record MoveToPosition(int left, int right) implements Command {
        public char letter() { return 'C'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code D,l,r}: wheel speeds in speed units (≈ 8 mm/s), −127..127; the robot enters speed mode. */
    record SetSpeed(int left, int right) implements Command {
        /** The stop command, {@code D,0,0}. */
        public static final SetSpeed STOP = new SetSpeed(0, 0);

        /** @param left left speed, units @param right right speed, units */
        public SetSpeed {
            check("D", "left speed", left, -127, 127);
            check("D", "right speed", right, -127, 127);
        }

        public char letter() { return 'D'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code E}: read the current wheel speeds; reply {@code e,l,r}, speed units. */
    record ReadSpeed() implements Command {
        public char letter() { return 'E'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 2; }
    }

    /** {@code F,Kp,Ki,Kd}: the position controller's PID gains (defaults 3000, 20, 4000). */
    record SetPositionPid(int kp, int ki, int kd) implements Command {
        public char letter() { return 'F'; }
        public int[] args() { return new int[] {kp, ki, kd}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code G,l,r}: set the 32-bit position counters, pulses ({@code G,0,0} resets them). */
    record SetPositionCounters(int left, int right) implements Command {
        public char letter() { return 'G'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code H}: read the position counters; reply {@code h,l,r}, pulses (≈ 0.08 mm). */
    record ReadPositionCounters() implements Command {
        public char letter() { return 'H'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 2; }
    }

    /** {@code I,ch}: read a 10-bit A/D channel; reply {@code i,v}. */
    record ReadAnalog(int channel) implements Command {
        /** @param channel the A/D channel, not negative */
        public ReadAnalog {
            check("I", "channel", channel, 0, 255);
        }

        public char letter() { return 'I'; }
        public int[] args() { return new int[] {channel}; }
        public int replyValueCount() { return 1; }
    }

    /** {@code J,vl,al,vr,ar}: speed and acceleration profile for {@code C} (defaults 20, 64). */
    record SetPositionProfile(int maxSpeedLeft, int accelerationLeft, int maxSpeedRight, int accelerationRight)
            implements Command {
        public char letter() { return 'J'; }
        public int[] args() { return new int[] {maxSpeedLeft, accelerationLeft, maxSpeedRight, accelerationRight}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code K}: motion status; reply {@code k,Tl,Ml,El,Tr,Mr,Er} (on target, mode, error per wheel). */
    record ReadMotionStatus() implements Command {
        public char letter() { return 'K'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 6; }
    }

    /** {@code L,n,a}: LED n (0 lateral, 1 front) off (0), on (1) or toggled (2). */
    record SetLed(int led, int action) implements Command {
        /** @param led 0 or 1 @param action 0 off, 1 on, 2 toggle */
        public SetLed {
            check("L", "LED", led, 0, 1);
            check("L", "action", action, 0, 2);
        }

        public char letter() { return 'L'; }
        public int[] args() { return new int[] {led, action}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code N}: the eight proximity values, 0..1023, higher = nearer; reply {@code n,v0,...,v7}. */
    record ReadProximity() implements Command {
        public char letter() { return 'N'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 8; }
    }

    /** {@code O}: the eight ambient-light values, lower = brighter; reply {@code o,v0,...,v7}. */
    record ReadLight() implements Command {
        public char letter() { return 'O'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return 8; }
    }

    /** {@code P,l,r}: raw motor PWM, −255..255. */
    record SetPwm(int left, int right) implements Command {
        /** @param left left PWM @param right right PWM */
        public SetPwm {
            check("P", "left PWM", left, -255, 255);
            check("P", "right PWM", right, -255, 255);
        }

        public char letter() { return 'P'; }
        public int[] args() { return new int[] {left, right}; }
        public int replyValueCount() { return 0; }
    }

    /** {@code R,a}: read a byte at address a of the extension bus; reply {@code r,v}. */
    record ReadBus(int address) implements Command {
        /** @param address 0..255 */
        public ReadBus {
            check("R", "address", address, 0, 255);
        }

        public char letter() { return 'R'; }
        public int[] args() { return new int[] {address}; }
        public int replyValueCount() { return 1; }
    }

    /** {@code W,data,a}: write a byte on the extension bus (data first, then address). */
    record WriteBus(int data, int address) implements Command {
        /** @param data 0..255 @param address 0..255 */
        public WriteBus {
            check("W", "data", data, 0, 255);
            check("W", "address", address, 0, 255);
        }

        public char letter() { return 'W'; }
        public int[] args() { return new int[] {data, address}; }
        public int replyValueCount() { return 0; }
    }

    /**
     * {@code T,id,<cmd>}: pass a command to turret {@code id} (1 = the gripper, 2 = the K213 vision turret); the reply
     * is {@code t,id,<reply>}.
     */
    record Turret(int id, TurretCommand body) implements Command {
        /** The gripper turret's id. */
        public static final int GRIPPER = 1;
        /** The K213 linear vision turret's id. */
        public static final int VISION = 2;

        /** @param id turret id, 0..255 @param body the turret's own command */
        public Turret {
            check("T", "turret id", id, 0, 255);
            if (body == null) {
                throw new IllegalArgumentException("T: a turret command needs a body, e.g. T,1,G");
            }
        }

        /** @param body a gripper command @return it, addressed to the gripper turret */
        public static Turret gripper(TurretCommand body) {
            return new Turret(GRIPPER, body);
        }

        /** @param body a K213 command @return it, addressed to the vision turret */
        public static Turret vision(TurretCommand body) {
            return new Turret(VISION, body);
        }

        public char letter() { return 'T'; }
        public int[] args() { return new int[0]; }
        public int replyValueCount() { return body.replyValueCount(); }
        public String replyHead() { return "t," + id + "," + Character.toLowerCase(body.letter()); }
        public String encode() { return "T," + id + "," + body.encode(); }
    }
}
