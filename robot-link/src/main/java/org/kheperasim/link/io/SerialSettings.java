package org.kheperasim.link.io;

/**
 * How to open a serial port. The Khepera's frame is 8 data bits, 2 stop bits, no parity, no flow
 * control; its baud rate is set by a jumper (9600 to 115200).
 *
 * @param path the port's path, e.g. {@code /dev/ttyUSB0} or {@code COM3}; virtual ports (socat)
 *     work by path too
 * @param baud bits per second
 * @param dataBits 5..8
 * @param stopBits 1 or 2
 * @param parity none, odd, even, mark or space
 * @param lineEnd what ends each command sent
 */
public record SerialSettings(String path, int baud, int dataBits, int stopBits, Parity parity, LineEnd lineEnd) {

    /** Parity bit setting. */
    public enum Parity { NONE, ODD, EVEN, MARK, SPACE }

    /** Checks the values and names the fix. */
    public SerialSettings {
        if (path == null || path.isBlank()) {
            throw new IllegalArgumentException("no serial port given: name one with --port, e.g. --port /dev/ttyUSB0"
                    + " (the 'ports' command lists them)");
        }
        if (baud < 300 || baud > 1_000_000) {
            throw new IllegalArgumentException("baud " + baud + " is not a serial line speed; the Khepera uses 9600,"
                    + " 19200, 38400, 57600 or 115200 (set by its mode jumper)");
        }
        if (dataBits < 5 || dataBits > 8) {
            throw new IllegalArgumentException("data bits " + dataBits + " must lie in 5..8; the Khepera uses 8");
        }
        if (stopBits != 1 && stopBits != 2) {
            throw new IllegalArgumentException("stop bits " + stopBits + " must be 1 or 2; the Khepera uses 2");
        }
    }

    /** @param path the port @param baud bits per second @return the Khepera's frame (8N2, LF) at that speed */
    public static SerialSettings khepera(String path, int baud) {
        return new SerialSettings(path, baud, 8, 2, Parity.NONE, LineEnd.LF);
    }
}
