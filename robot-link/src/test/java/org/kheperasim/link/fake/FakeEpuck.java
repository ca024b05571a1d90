package org.kheperasim.link.fake;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * An e-puck that lives in the tests, written from its firmware's ASCII command loop (GCtronic's SerCom,
 * {@code asercom}: e-puck1 SerCom 1.1.3 of 2006 and the e-puck2's asercom2) and not from robot-link's
 * codec, so that a test of robot-link against it checks robot-link, not the codec against itself.
 *
 * <p>As the firmware does: a line ends at CR or LF; the letter is upper-cased (lower case is
 * accepted); arguments are read like {@code sscanf("D,%d,%d")}, so missing or unreadable ones keep
 * their last values and a known letter is never refused; every reply ends in CR LF; an unknown letter
 * gets {@code z,Command not found}; {@code R} answers {@code r} and prints the welcome banner again.
 * The step counters advance with the speeds (steps/s), so a controller's positions move.
 */
public final class FakeEpuck implements AutoCloseable {
    /** The welcome banner the firmware prints at start-up and after {@code R}. */
    public static final String BANNER = "\f\007WELCOME to the SerCom protocol on e-Puck\r\n"
            + "the EPFL education robot type \"H\" for help\r\n";

    private final InputStream in;
    private final OutputStream out;
    private final List<String> received = Collections.synchronizedList(new ArrayList<>());
    private final Thread thread;

    private final int[] proximity = new int[8];
    private final int[] light = {3800, 3800, 3800, 3800, 3800, 3800, 3800, 3800};
    private int speedLeft;
    private int speedRight;
    private double stepsLeft;
    private double stepsRight;
    private long lastUpdate = System.nanoTime();
    private int leds;

    /** @param in command bytes from the host @param out reply bytes to the host */
    public FakeEpuck(InputStream in, OutputStream out) {
        this.in = in;
        this.out = out;
        this.thread = new Thread(this::serve, "fake-epuck");
        thread.setDaemon(true);
    }

    /** @return this fake, answering, after its welcome banner */
    public FakeEpuck start() {
        write(BANNER);
        thread.start();
        return this;
    }

    private void serve() {
        StringBuilder line = new StringBuilder();
        try {
            int b;
            while ((b = in.read()) >= 0) {
                if (b == '\r' || b == '\n') {
                    if (line.length() > 0) {
                        handle(line.toString());
                        line.setLength(0);
                    }
                } else {
                    line.append((char) b);
                }
            }
        } catch (IOException e) {
            // the link has gone: this robot is switched off
        }
    }

    private synchronized void handle(String text) {
        received.add(text);
        advance();
        String[] f = text.split(",", -1);
        char letter = Character.toUpperCase(text.charAt(0));
        String reply;
        switch (letter) {
            case 'B' -> { leds = bit(leds, 8, arg(f, 1, 0)); reply = "b"; }
            case 'D' -> { speedLeft = arg(f, 1, speedLeft); speedRight = arg(f, 2, speedRight); reply = "d"; }
            case 'E' -> reply = "e," + speedLeft + "," + speedRight;
            case 'F' -> { leds = bit(leds, 9, arg(f, 1, 0)); reply = "f"; }
            case 'H' -> reply = "\n\"A\"         Accelerometer\r\n"
                    + "\"D,#,#\"     Set motor speed left,right\r\n"
                    + "\"N\"         Proximity\r\n"
                    + "\"Q\"         Get motor position left,right\r\n"
                    + "\"V\"         Version of SerCom";
            case 'L' -> {
                int n = arg(f, 1, 0);
                int a = arg(f, 2, 0);
                for (int led = n == 8 ? 0 : n; led <= (n == 8 ? 7 : n); led++) {
                    leds = bit(leds, led, a);
                }
                reply = "l";
            }
            case 'N' -> reply = "n," + join(proximity);
            case 'O' -> reply = "o," + join(light);
            case 'P' -> { stepsLeft = arg(f, 1, 0); stepsRight = arg(f, 2, 0); reply = "p"; }
            case 'Q' -> reply = "q," + (int) stepsLeft + "," + (int) stepsRight;
            case 'R' -> {
                speedLeft = 0;
                speedRight = 0;
                stepsLeft = 0;
                stepsRight = 0;
                leds = 0;
                write("r\r\n" + BANNER);
                return;
            }
            case 'S' -> { speedLeft = 0; speedRight = 0; leds = 0; reply = "s"; }
            case 'V' -> reply = "v,Version 1.1.3 September 2006";
            default -> reply = "z,Command not found";
        }
        write(reply + "\r\n");
    }

    /** Like sscanf: the i-th field as an integer, or {@code otherwise} when it is missing or not a number. */
    private static int arg(String[] fields, int i, int otherwise) {
        try {
            return i < fields.length ? Integer.parseInt(fields[i].strip()) : otherwise;
        } catch (NumberFormatException e) {
            return otherwise;
        }
    }

    private static int bit(int mask, int bit, int action) {
        return switch (action) {
            case 0 -> mask & ~(1 << bit);
            case 1 -> mask | (1 << bit);
            default -> mask ^ (1 << bit);
        };
    }

    private static String join(int[] v) {
        StringBuilder b = new StringBuilder();
        for (int x : v) {
            b.append(b.length() == 0 ? "" : ",").append(x);
        }
        return b.toString();
    }

    private void advance() {
        long now = System.nanoTime();
        double seconds = (now - lastUpdate) / 1e9;
        // The firmware's motor library limits speeds to ±1000 steps/s.
        stepsLeft += StrictMath.max(-1000, StrictMath.min(1000, speedLeft)) * seconds;
        stepsRight += StrictMath.max(-1000, StrictMath.min(1000, speedRight)) * seconds;
        lastUpdate = now;
    }

    private synchronized void write(String text) {
        try {
            out.write(text.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
        } catch (IOException e) {
            // the host has gone
        }
    }

    /** @param values eight proximity values the robot reports (higher = nearer) */
    public synchronized void setProximity(int... values) {
        System.arraycopy(values, 0, proximity, 0, 8);
    }

    /** @return every command line received, in order */
    public List<String> received() {
        synchronized (received) {
            return List.copyOf(received);
        }
    }

    /** @return the last command line received, or null */
    public String lastReceived() {
        synchronized (received) {
            return received.isEmpty() ? null : received.get(received.size() - 1);
        }
    }

    /** @return {left, right} speeds last set, steps/s */
    public synchronized int[] speeds() {
        return new int[] {speedLeft, speedRight};
    }

    /** @return the LEDs as a mask: ring LEDs 0..7, body LED bit 8, front LED bit 9 */
    public synchronized int leds() {
        return leds;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "fake e-puck (%d commands)", received.size());
    }

    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            // closed already
        }
        try {
            out.close();
        } catch (IOException e) {
            // closed already
        }
    }
}
