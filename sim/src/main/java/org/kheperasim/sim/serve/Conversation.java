package org.kheperasim.sim.serve;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.timing.LinkTiming;

/**
 * One client's conversation with the served robot: its command lines read one by one and each
 * answered when its characters, the robot's turnaround and the reply's characters would have
 * passed on the wire at the set baud (divided by the robot's speed factor), in the robot's {@link
 * Dialect} (its letters, errors and line ends). Garbage gets the robot's own error reply; an
 * over-long line is answered once and thrown away.
 */
final class Conversation {
    private final ServedRobot robot;
    private final Consumer<String> note;
    private final AtomicLong commands;

    Conversation(ServedRobot robot, Consumer<String> note, AtomicLong commands) {
        this.robot = robot;
        this.note = note;
        this.commands = commands;
    }

    /** Read lines, answer each at its wire time; returns at end of stream. */
    void handle(InputStream rawIn, OutputStream out) throws IOException {
        InputStream in = new BufferedInputStream(rawIn, 1024);
        LinkTiming timing = robot.timing();
        Dialect dialect = robot.dialect();
        double speed = robot.speed();
        StringBuilder line = new StringBuilder(ProtocolServer.MAX_LINE_CHARS);
        boolean overflow = false;
        long lineFree = System.nanoTime();
        while (true) {
            int b = in.read();
            if (b < 0) {
                return;
            }
            if (b != '\r' && b != '\n') {
                if (overflow) {
                    continue;
                }
                if (line.length() >= ProtocolServer.MAX_LINE_CHARS) {
                    // Answer once and throw the rest away up to the next terminator, unstored.
                    overflow = true;
                    line.setLength(0);
                    note.accept("a line longer than " + ProtocolServer.MAX_LINE_CHARS
                            + " characters was refused with " + dialect.overlongReply());
                    lineFree = reply(out, timing, dialect, speed, lineFree, ProtocolServer.MAX_LINE_CHARS + 1,
                            dialect.overlongReply());
                    continue;
                }
                line.append((char) b);
                continue;
            }
            if (overflow) {
                overflow = false;
                continue;
            }
            if (line.length() == 0) {
                continue;
            }
            String text = line.toString();
            line.setLength(0);
            Command command;
            try {
                command = dialect.parseCommand(text);
            } catch (ProtocolException e) {
                lineFree = reply(out, timing, dialect, speed, lineFree, text.length() + 1, dialect.errorReply(e));
                continue;
            }
            lineFree = reply(out, timing, dialect, speed, lineFree, text.length() + 1, command);
        }
    }

    /**
     * Wait for the command's wire time and the turnaround, act, wait for the reply's wire time,
     * send it.
     *
     * @param dialect the protocol answered in: its line end ends the reply
     * @param answer a {@link Command} to execute, or a fixed error line
     * @return when the line is free for the next command, System.nanoTime()
     */
    private long reply(OutputStream out, LinkTiming timing, Dialect dialect, double speed, long lineFree,
            int commandChars, Object answer) throws IOException {
        long start = StrictMath.max(System.nanoTime(), lineFree);
        long actAt = start + (long) ((timing.wireNanos(commandChars) + timing.turnaroundNanos()) / speed);
        sleepUntil(actAt);
        String text;
        if (answer instanceof Command.Turret t && t.id() == Command.Turret.VISION) {
            text = vision(t);
        } else if (answer instanceof Command c) {
            text = robot.execute(c);
        } else {
            text = (String) answer;
        }
        String wire = text + dialect.replyEnd();
        long sendAt = actAt + (long) (timing.wireNanos(wire.length()) / speed);
        sleepUntil(sendAt);
        out.write(wire.getBytes(StandardCharsets.ISO_8859_1));
        out.flush();
        commands.incrementAndGet();
        return sendAt;
    }

    /**
     * The K213 vision turret's answer ({@code docs/protocol-server.md}): {@code B} its version,
     * {@code N} the 64 pixels, {@code O} and {@code P} the brightest and darkest pixel's index; any
     * other command is not the turret's.
     */
    private String vision(Command.Turret c) {
        TurretCommand body = c.body();
        return robot.inspect(r -> {
            long now = robot.timeNanos();
            if (body instanceof TurretCommand.Image) {
                return c.reply(r.vision().image(now)).encode();
            } else if (body instanceof TurretCommand.BrightestPixel) {
                return c.reply(r.vision().brightest(now)).encode();
            } else if (body instanceof TurretCommand.DarkestPixel) {
                return c.reply(r.vision().darkest(now)).encode();
            } else if (body instanceof TurretCommand.Version) {
                return c.reply(VISION_VERSION).encode();
            }
            return KheperaProtocol.COMMAND_NOT_FOUND;
        });
    }

    /** The vision turret's version and revision, {@code T,2,B}. */
    static final int[] VISION_VERSION = {1, 0};

    private static void sleepUntil(long deadline) {
        long left;
        while ((left = deadline - System.nanoTime()) > 0) {
            LockSupport.parkNanos(left);
        }
    }

}
