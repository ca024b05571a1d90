package org.kheperasim.link.protocol;

import java.util.List;

/**
 * A reply from the robot, checked against the command it answers: the head (reply letter, and
 * for a turret reply {@code t,id,letter}) matched, and the values are the fields after it.
 *
 * @param command the command this reply answers
 * @param values the fields after the head, as sent (decimal integers, or version strings for {@code b})
 */
public record Reply(Command command, List<String> values) {

    /** @param command the command answered @param values its fields after the head */
    public Reply {
        values = List.copyOf(values);
    }

    /**
     * @param index 0-based field after the head
     * @return that field as an integer
     */
    public int intValue(int index) {
        return Integer.parseInt(values.get(index));
    }

    /** @return every field as an integer */
    public int[] ints() {
        int[] v = new int[values.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = intValue(i);
        }
        return v;
    }

    /** @return the reply line as the robot sends it, without CR LF */
    public String encode() {
        StringBuilder b = new StringBuilder(command.replyHead());
        for (String v : values) {
            b.append(',').append(v);
        }
        return b.toString();
    }

    @Override
    public String toString() {
        return encode();
    }
}
