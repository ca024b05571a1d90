package org.kheperasim.link.cli;

import java.io.IOException;
import java.io.PrintWriter;
import org.kheperasim.link.io.LineEnd;
import org.kheperasim.link.io.Link;
import org.kheperasim.link.io.Links;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.tool.CliNumbers;
import picocli.CommandLine.Option;

/** The connection options every command shares: a serial port (or a TCP address) and its frame. */
public final class Connection {
    @Option(names = "--port", required = true, paramLabel = "PATH",
            description = "Serial port path (e.g. /dev/ttyUSB0, COM3, a socat pty link) or tcp://HOST:PORT.")
    String port;

    @Option(names = "--baud", converter = CliNumbers.Baud.class,
            description = "Line speed: 9600, 19200, 38400, 57600 or 115200 (the robot's mode jumper). Default: 38400"
                    + " (115200 with --dialect epuck).")
    Integer baud;

    @Option(names = "--dialect", paramLabel = "NAME", defaultValue = Dialect.DEFAULT,
            description = "The robot's protocol: khepera1, khepera2 or epuck (a Bluetooth serial port is"
                    + " a serial port). Default: ${DEFAULT-VALUE}.")
    String dialect;

    /** @return the robot's protocol ({@code --dialect}) */
    Dialect dialect() {
        return Dialect.named(dialect);
    }

    /** @return the line speed: {@code --baud}, or the dialect's usual one */
    int baud() {
        return baud != null ? baud : dialect().defaultBaud();
    }

    @Option(names = "--data-bits", defaultValue = "8", description = "Data bits. Default: ${DEFAULT-VALUE}.")
    int dataBits;

    @Option(names = "--stop-bits", defaultValue = "2", description = "Stop bits, 1 or 2. Default: ${DEFAULT-VALUE}.")
    int stopBits;

    @Option(names = "--parity", defaultValue = "NONE",
            description = "Parity: ${COMPLETION-CANDIDATES}. Default: ${DEFAULT-VALUE}.")
    SerialSettings.Parity parity;

    @Option(names = "--eol", defaultValue = "LF",
            description = "What ends each command: CR or LF (send exactly one). Default: ${DEFAULT-VALUE}.")
    LineEnd eol;

    @Option(names = "--timeout", defaultValue = "300", paramLabel = "MS", converter = CliNumbers.PositiveLong.class,
            description = "Reply timeout beyond the reply's wire time, ms. Default: ${DEFAULT-VALUE}.")
    long timeoutMillis;

    @Option(names = "--retries", defaultValue = "3", converter = CliNumbers.NonNegativeInt.class,
            description = "Times a command with no reply is sent again. Default: ${DEFAULT-VALUE}.")
    int retries;

    /** @return the serial settings these options give */
    SerialSettings settings() {
        if (timeoutMillis > 600_000 || retries > 100) {
            throw new IllegalArgumentException("--timeout " + timeoutMillis + " ms / --retries " + retries
                    + ": give at most 600000 ms and 100 retries");
        }
        if (eol == LineEnd.CRLF) {
            throw new IllegalArgumentException("--eol CRLF: a command ends with exactly one CR or LF; give CR or LF");
        }
        return new SerialSettings(port, baud(), dataBits, stopBits, parity, eol);
    }

    /** @return the link timing at this baud */
    LinkTiming timing() {
        return new LinkTiming(baud(), 1 + dataBits + stopBits + (parity == SerialSettings.Parity.NONE ? 0 : 1),
                LinkTiming.DEFAULT_TURNAROUND_NANOS);
    }

    /**
     * @param out where to say what is being opened
     * @return a session on the opened link (not yet handshaken)
     */
    Session open(PrintWriter out) throws IOException {
        Dialect d = dialect();
        SerialSettings s = settings();
        Link link = Links.open(s);
        out.println("opened " + link.describe());
        out.flush();
        return new Session(link, timing(), new Session.Options(timeoutMillis, retries, 200, 3000), d);
    }
}
