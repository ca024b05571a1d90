package org.kheperasim.link.fake;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.Reply;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.timing.LinkTiming;

/**
 * A Khepera that lives in the tests: it reads command lines from a byte stream and answers every
 * command of the reference as the robot does, using the codec's server side. It can delay each
 * reply by its wire time, and inject faults: noise, a dropped reply, a late reply, a boot banner
 * mid-session, and going silent (the robot vanishing).
 *
 * <p>Its wheels turn: the position counters advance with the commanded speeds (1 unit = 1 pulse
 * per 10 ms), so a controller sees its encoders move.
 */
public final class FakeKhepera implements AutoCloseable {
    /** What a Khepera prints after power-up or reset (the manual's banner, in substance). */
    public static final String BANNER = "\r\nKhepera BIOS version 5.02\r\nProtocol version 5.01\r\n";

    private final InputStream in;
    private final OutputStream out;
    private final List<String> received = Collections.synchronizedList(new ArrayList<>());
    private final Thread thread;
    private volatile LinkTiming timing;
    private volatile long replyDelayMillis;

    // Faults, each used once unless stated.
    private final AtomicInteger dropReplies = new AtomicInteger();
    private final AtomicLong lateReplyMillis = new AtomicLong();
    private volatile String noiseBeforeReply;
    private volatile boolean bannerBeforeReply;
    private volatile boolean silent;
    private volatile boolean gripperFitted = true;
    private volatile boolean visionFitted = true;
    private final FakeLinearTurret vision = new FakeLinearTurret();

    // Robot state.
    private final int[] proximity = new int[8];
    private final int[] light = {480, 480, 480, 480, 480, 480, 480, 480};
    private volatile int left;
    private volatile int right;
    private double posLeft;
    private double posRight;
    private long lastUpdate = System.nanoTime();
    private volatile boolean fingersClosed;
    private volatile int arm = 190;
    private volatile int barrier;
    private volatile int resistivity;
    private final AtomicInteger replies = new AtomicInteger();
    /** What the sensors see as the wheels move; null: the values set by {@link #setProximity}. */
    private volatile Scene scene;

    /** A world around the fake robot: its sensors answer from it and its wheels move in it. */
    public interface Scene {
        /** @param leftPulses left wheel's travel, encoder pulses @param rightPulses right wheel's */
        void moved(double leftPulses, double rightPulses);

        /** @return the eight proximity readings now */
        int[] proximity();

        /** @return the eight ambient-light readings now */
        int[] light();
    }
    private final AtomicInteger lateReplies = new AtomicInteger();

    /**
     * @param in command bytes from the host
     * @param out reply bytes to the host
     * @param timing when not null, each reply waits the exchange's wire time (a pty is as fast as memory)
     */
    public FakeKhepera(InputStream in, OutputStream out, LinkTiming timing) {
        this.in = in;
        this.out = out;
        this.timing = timing;
        this.thread = new Thread(this::serve, "fake-khepera");
        thread.setDaemon(true);
    }

    /** @return this fake, answering */
    public FakeKhepera start() {
        thread.start();
        return this;
    }

    private void serve() {
        StringBuilder line = new StringBuilder();
        byte[] buf = new byte[256];
        try {
            while (true) {
                int n = in.read(buf);
                if (n < 0) {
                    return;
                }
                for (int i = 0; i < n; i++) {
                    char c = (char) (buf[i] & 0xff);
                    if (c == '\r' || c == '\n') {
                        if (line.length() > 0) {
                            handle(line.toString());
                            line.setLength(0);
                        }
                    } else {
                        line.append(c);
                    }
                }
            }
        } catch (IOException e) {
            // the pty or socket has gone: this robot is switched off
        }
    }

    private void handle(String text) throws IOException {
        received.add(text);
        String answer;
        Command command = null;
        try {
            command = KheperaProtocol.parseCommand(text);
            answer = answer(command).encode();
        } catch (ProtocolException e) {
            answer = KheperaProtocol.errorReply(e);
        }
        if (silent) {
            return;
        }
        if (timing != null) {
            LockSupport.parkNanos(timing.exchangeNanos(text.length() + 1, answer.length() + 2));
        }
        if (replyDelayMillis > 0) {
            LockSupport.parkNanos(replyDelayMillis * 1_000_000L);
        }
        if (dropReplies.get() > 0 && dropReplies.getAndDecrement() > 0) {
            return;
        }
        long late = lateReplyMillis.getAndSet(0);
        if (late > 0) {
            String lateAnswer = answer;
            Thread t = new Thread(() -> {
                LockSupport.parkNanos(late * 1_000_000L);
                write(lateAnswer + KheperaProtocol.REPLY_END);
                synchronized (lateReplies) {
                    lateReplies.incrementAndGet();
                    lateReplies.notifyAll();
                }
            }, "fake-khepera-late-reply");
            t.setDaemon(true);
            t.start();
            return;
        }
        StringBuilder b = new StringBuilder();
        if (bannerBeforeReply) {
            bannerBeforeReply = false;
            reset();
            // A reset robot forgets the command it was given: only the banner comes back.
            write(BANNER);
            return;
        }
        String noise = noiseBeforeReply;
        if (noise != null) {
            noiseBeforeReply = null;
            b.append(noise);
        }
        b.append(answer).append(KheperaProtocol.REPLY_END);
        write(b.toString());
        replies.incrementAndGet();
    }

    private synchronized void write(String text) {
        try {
            out.write(text.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
        } catch (IOException e) {
            // the host has gone
        }
    }

    private synchronized void reset() {
        left = 0;
        right = 0;
        posLeft = 0;
        posRight = 0;
    }

    private synchronized void advanceWheels() {
        long now = System.nanoTime();
        double ticks = (now - lastUpdate) / 10_000_000.0;
        posLeft += left * ticks;
        posRight += right * ticks;
        lastUpdate = now;
        Scene sc = scene;
        if (sc != null && (left != 0 || right != 0)) {
            sc.moved(left * ticks, right * ticks);
        }
    }

    private Reply answer(Command c) {
        advanceWheels();
        if (c instanceof Command.ReadVersion b) {
            return b.reply("5.02", "5.01");
        } else if (c instanceof Command.SetSpeed d) {
            left = d.left();
            right = d.right();
            return d.reply();
        } else if (c instanceof Command.ReadSpeed) {
            return c.reply(left, right);
        } else if (c instanceof Command.SetPositionCounters g) {
            synchronized (this) {
                posLeft = g.left();
                posRight = g.right();
            }
            return c.reply();
        } else if (c instanceof Command.ReadPositionCounters) {
            synchronized (this) {
                return c.reply((int) posLeft, (int) posRight);
            }
        } else if (c instanceof Command.ReadAnalog a) {
            return c.reply(100 + a.channel());
        } else if (c instanceof Command.ReadMotionStatus) {
            return c.reply(0, 0, 0, 0, 0, 0);
        } else if (c instanceof Command.MoveToPosition m && scene != null) {
            // With a scene, a position move ends at once: the wheels are where they were sent.
            synchronized (this) {
                scene.moved(m.left() - posLeft, m.right() - posRight);
                posLeft = m.left();
                posRight = m.right();
            }
            return c.reply();
        } else if (c instanceof Command.ReadProximity) {
            return c.reply(scene != null ? scene.proximity() : proximity.clone());
        } else if (c instanceof Command.ReadLight) {
            return c.reply(scene != null ? scene.light() : light.clone());
        } else if (c instanceof Command.ReadBus) {
            return c.reply(0);
        } else if (c instanceof Command.Turret t && t.id() == Command.Turret.VISION && visionFitted) {
            TurretCommand body = t.body();
            if (body instanceof TurretCommand.Image) {
                return c.reply(vision.image());
            } else if (body instanceof TurretCommand.BrightestPixel) {
                return c.reply(vision.brightest());
            } else if (body instanceof TurretCommand.DarkestPixel) {
                return c.reply(vision.darkest());
            } else if (body instanceof TurretCommand.Version) {
                return c.reply(1, 2);
            }
            throw new ProtocolException(ProtocolException.Kind.UNKNOWN_COMMAND, c.encode(), "unknown vision command");
        } else if (c instanceof Command.Turret t) {
            if (t.id() != Command.Turret.GRIPPER || !gripperFitted) {
                throw new ProtocolException(ProtocolException.Kind.UNKNOWN_COMMAND, c.encode(), "no turret " + t.id());
            }
            TurretCommand body = t.body();
            if (body instanceof TurretCommand.Fingers f) {
                fingersClosed = f.close();
                return c.reply();
            } else if (body instanceof TurretCommand.Arm a) {
                arm = a.position();
                return c.reply();
            } else if (body instanceof TurretCommand.Resistivity) {
                return c.reply(fingersClosed ? resistivity : 0);
            } else if (body instanceof TurretCommand.Barrier) {
                return c.reply(barrier);
            } else if (body instanceof TurretCommand.MotorPosition m) {
                return c.reply(m.motor() == 1 ? arm : (fingersClosed ? 200 : 0));
            } else if (body instanceof TurretCommand.Version) {
                return c.reply(2, 1);
            }
            throw new ProtocolException(ProtocolException.Kind.UNKNOWN_COMMAND, c.encode(), "unknown gripper command");
        }
        // A, C, F, J, L, P, W: acknowledged with their letter.
        return c.reply();
    }

    // ------------------------------------------------------------------ set the scene

    /** @param s the world its sensors answer from and its wheels move in (null: none) */
    public void setScene(Scene s) {
        scene = s;
    }

    /** @param values eight proximity values the robot reports */
    public void setProximity(int... values) {
        System.arraycopy(values, 0, proximity, 0, 8);
    }

    /** @param values eight ambient-light values */
    public void setLight(int... values) {
        System.arraycopy(values, 0, light, 0, 8);
    }

    /** @param present something between the fingers @param value its resistivity */
    public void setObject(boolean present, int value) {
        barrier = present ? 1 : 0;
        resistivity = value;
    }

    /** @param fitted whether the gripper turret answers */
    public void setGripperFitted(boolean fitted) {
        gripperFitted = fitted;
    }

    /** @param fitted whether the K213 vision turret answers */
    public void setVisionFitted(boolean fitted) {
        visionFitted = fitted;
    }

    /** @return the K213 vision turret on top of this robot: set what it sees */
    public FakeLinearTurret vision() {
        return vision;
    }

    /** @return the position counters now, [left, right], pulses */
    public synchronized int[] positions() {
        advanceWheels();
        return new int[] {(int) posLeft, (int) posRight};
    }

    /** @param t wire timing to delay replies by, or null for none */
    public void setTiming(LinkTiming t) {
        timing = t;
    }

    // ------------------------------------------------------------------ faults

    /** @param millis answer every command this much later: a robot (or the fake) starved by a loaded machine */
    public void setReplyDelay(long millis) {
        replyDelayMillis = millis;
    }

    /** @param n replies to swallow (the command is still obeyed) */
    public void dropReplies(int n) {
        dropReplies.set(n);
    }

    /** @param millis delay the next reply by this much (it arrives after the host has given up on it) */
    public void lateReply(long millis) {
        lateReplyMillis.set(millis);
    }

    /** @param noise characters to send just before the next reply */
    public void noiseBeforeNextReply(String noise) {
        noiseBeforeReply = noise;
    }

    /** Reset at the next command: answer it with the boot banner only, and stop the wheels. */
    public void resetAtNextCommand() {
        bannerBeforeReply = true;
    }

    /** Send the boot banner now, unasked (power-up). */
    public void sendBanner() {
        write(BANNER);
    }

    /** @param on the robot stops answering (it still hears, and records what it hears) */
    public void setSilent(boolean on) {
        silent = on;
    }

    // ------------------------------------------------------------------ what happened

    /** @return every line received, in order */
    public List<String> received() {
        synchronized (received) {
            return new ArrayList<>(received);
        }
    }

    /** @return the last line received, or null */
    public String lastReceived() {
        synchronized (received) {
            return received.isEmpty() ? null : received.get(received.size() - 1);
        }
    }

    /** @return the wheel speeds now, [left, right] */
    public int[] speeds() {
        return new int[] {left, right};
    }

    /** @return whether the fingers are closed */
    public boolean fingersClosed() {
        return fingersClosed;
    }

    /** @return the arm position last commanded */
    public int arm() {
        return arm;
    }

    /**
     * Wait until this many late replies have been written (a test that needs one on the line, whatever the load).
     *
     * @param n late replies written so far
     * @param maxMillis the longest wait
     * @throws IllegalStateException when they were not written in time
     */
    public void awaitLateReplies(int n, long maxMillis) throws InterruptedException {
        long end = System.nanoTime() + maxMillis * 1_000_000L;
        synchronized (lateReplies) {
            while (lateReplies.get() < n) {
                long left = (end - System.nanoTime()) / 1_000_000L;
                if (left <= 0) {
                    throw new IllegalStateException(lateReplies.get() + " of " + n + " late replies written in " + maxMillis + " ms");
                }
                lateReplies.wait(left);
            }
        }
    }

    /** @return replies sent */
    public int replies() {
        return replies.get();
    }

    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            // already gone
        }
        try {
            out.close();
        } catch (IOException e) {
            // already gone
        }
    }
}
