package org.kheperasim.link.protocol;

/**
 * A command for a turret, sent inside {@code T,id,<cmd>}. The gripper turret's (id 1) and the K213
 * vision turret's (id 2) commands are typed; any other text is carried as {@link Raw}.
 *
 * <p>The K213's commands are those of Appendix A of its manual (K213 Vision Turret User Manual,
 * K-Team, version 1.2, 1999, "Communication protocol to control the K213 vision turret"), as two
 * independent clients of the real turret use them: {@code N} reads the image, {@code O} and
 * {@code P} the brightest and darkest pixel's position, {@code B} the version.
 */
public sealed interface TurretCommand {

    /** @return the command letter, upper case */
    char letter();

    /** @return the command text after {@code T,id,}, e.g. {@code E,190} */
    String encode();

    /** @return how many values follow {@code t,id,x} in the reply; -1 when unknown */
    int replyValueCount();

    /** Arm position at or above which ({@code <=}) the arm counts as up: larger values are lower. */
    int ARM_UP = 180;
    /** The usual arm-down position. */
    int ARM_DOWN = 249;

    /** {@code D,0} opens, {@code D,1} closes the fingers; reply {@code t,1,d}. */
    record Fingers(boolean close) implements TurretCommand {
        public char letter() { return 'D'; }
        public String encode() { return "D," + (close ? 1 : 0); }
        public int replyValueCount() { return 0; }
    }

    /** {@code E,pos}: move the arm, 0..255, larger = lower (up ≈ 175–190, down ≈ 240–255); reply {@code t,1,e}. */
    record Arm(int position) implements TurretCommand {
        /** @param position 0..255 */
        public Arm {
            if (position < 0 || position > 255) {
                throw new IllegalArgumentException("T,1,E: arm position " + position + " is outside 0..255"
                        + " (larger = lower; up is about 180, down about 250)");
            }
        }

        public char letter() { return 'E'; }
        public String encode() { return "E," + position; }
        public int replyValueCount() { return 0; }
    }

    /** {@code F}: resistivity of what is between the fingers; reply {@code t,1,f,v}. */
    record Resistivity() implements TurretCommand {
        public char letter() { return 'F'; }
        public String encode() { return "F"; }
        public int replyValueCount() { return 1; }
    }

    /** {@code G}: the optical barrier between the fingers, 0 = nothing there; reply {@code t,1,g,v}. */
    record Barrier() implements TurretCommand {
        public char letter() { return 'G'; }
        public String encode() { return "G"; }
        public int replyValueCount() { return 1; }
    }

    /** {@code H,0} gripper, {@code H,1} arm motor position; reply {@code t,1,h,v} (uncertain in the sources). */
    record MotorPosition(int motor) implements TurretCommand {
        /** @param motor 0 gripper, 1 arm */
        public MotorPosition {
            if (motor != 0 && motor != 1) {
                throw new IllegalArgumentException("T,1,H: motor " + motor + " must be 0 (gripper) or 1 (arm)");
            }
        }

        public char letter() { return 'H'; }
        public String encode() { return "H," + motor; }
        public int replyValueCount() { return 1; }
    }

    /**
     * K213 {@code N}: the image, 64 grey levels 0..255, pixel 0 the leftmost of the 36° field of
     * view; reply {@code t,2,n,v0,...,v63}.
     */
    record Image() implements TurretCommand {
        /** Pixels in a K213 image. */
        public static final int PIXELS = 64;

        public char letter() { return 'N'; }
        public String encode() { return "N"; }
        public int replyValueCount() { return PIXELS; }
    }

    /** K213 {@code O}: the index, 0..63, of the brightest pixel; reply {@code t,2,o,k}. */
    record BrightestPixel() implements TurretCommand {
        public char letter() { return 'O'; }
        public String encode() { return "O"; }
        public int replyValueCount() { return 1; }
    }

    /** K213 {@code P}: the index, 0..63, of the darkest pixel; reply {@code t,2,p,k}. */
    record DarkestPixel() implements TurretCommand {
        public char letter() { return 'P'; }
        public String encode() { return "P"; }
        public int replyValueCount() { return 1; }
    }

    /** {@code B}: the turret's version; reply {@code t,id,b,v,r}. */
    record Version() implements TurretCommand {
        public char letter() { return 'B'; }
        public String encode() { return "B"; }
        public int replyValueCount() { return 2; }
    }

    /**
     * Any other turret command, passed through as text (for turrets other than the gripper).
     *
     * @param text the command after {@code T,id,}, starting with its letter
     */
    record Raw(String text) implements TurretCommand {
        /**
         * @param text starts with an ASCII letter; printable ASCII only, so that it goes on the wire as
         *     one command (a line break inside would end the command early and send the rest as another)
         */
        public Raw {
            if (text == null || text.isEmpty() || !isAsciiLetter(text.charAt(0))) {
                throw new IllegalArgumentException("T: turret command '" + printable(text)
                        + "' must start with a letter A-Z or a-z");
            }
            for (int i = 0; i < text.length(); i++) {
                char c = text.charAt(i);
                if (c < 0x20 || c > 0x7E) {
                    throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                            "T: turret command '%s' has the character U+%04X at position %d; a command is one line"
                                    + " of printable ASCII (no line breaks or control characters)", printable(text),
                                    (int) c, i + 1));
                }
            }
        }

        private static boolean isAsciiLetter(char c) {
            return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
        }

        /** The text with control and non-ASCII characters shown as U+XXXX, at most 60 characters. */
        private static String printable(String text) {
            if (text == null) {
                return "null";
            }
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < text.length() && b.length() < 60; i++) {
                char c = text.charAt(i);
                b.append(c >= 0x20 && c <= 0x7E ? String.valueOf(c)
                        : String.format(java.util.Locale.ROOT, "U+%04X", (int) c));
            }
            return b.toString();
        }

        public char letter() { return Character.toUpperCase(text.charAt(0)); }
        public String encode() { return text; }
        public int replyValueCount() { return -1; }
    }
}
