package org.kheperasim.link.io;

import com.fazecast.jSerialComm.SerialPort;
import com.fazecast.jSerialComm.SerialPortInvalidPortException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A serial port through jSerialComm. This is the only class that calls jSerialComm. Ports open by
 * path, so virtual ports (a socat pty pair), which jSerialComm does not enumerate, work too.
 */
public final class SerialLink extends ByteLink {
    /** A Windows port name: COM1, com10, or the long form {@code \\.\COM10} that Windows needs from COM10 on. */
    private static final java.util.regex.Pattern WINDOWS_NAME =
            java.util.regex.Pattern.compile("(?i)(\\\\\\\\\\.\\\\)?COM[0-9]+");
    /** Read timeout of one native read; a longer wait loops, a byte arriving ends it at once. */
    private static final int READ_SLICE_MILLIS = 20;

    /** A serial port the system lists. @param path its path @param description what the system calls it */
    public record PortInfo(String path, String description) {
    }

    private final SerialPort port;
    private final SerialSettings settings;
    private volatile boolean closed;

    private SerialLink(SerialPort port, SerialSettings settings) {
        super(settings.lineEnd());
        this.port = port;
        this.settings = settings;
    }

    /** @return the serial ports the system lists (virtual ports such as socat's are not among them) */
    public static List<PortInfo> listPorts() {
        List<PortInfo> ports = new ArrayList<>();
        for (SerialPort p : SerialPort.getCommPorts()) {
            ports.add(new PortInfo(p.getSystemPortPath(),
                    p.getDescriptivePortName() + " (" + p.getPortDescription() + ")"));
        }
        return ports;
    }

    /**
     * Open a port.
     *
     * @param settings path and frame
     * @return the open link
     * @throws IOException naming the port and the likely fix when it cannot be opened
     */
    public static SerialLink open(SerialSettings settings) throws IOException {
        String path = settings.path();
        boolean windows = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).startsWith("windows");
        boolean windowsName = WINDOWS_NAME.matcher(path).matches();
        if (windowsName && !windows) {
            throw new IOException("cannot open serial port " + path + ": COM names are Windows's, and this is "
                    + System.getProperty("os.name") + ", where a serial port is a path such as /dev/ttyUSB0 (Linux) or"
                    + " /dev/cu.usbserial-* (macOS); 'ports' lists the ports this machine has");
        }
        if (!windowsName && !Files.exists(Path.of(path))) {
            throw new IOException("cannot open serial port " + path + ": it does not exist. Check that the cable or"
                    + " USB adapter is plugged in; 'ports' lists the ports this machine has");
        }
        SerialPort port;
        try {
            port = SerialPort.getCommPort(path);
        } catch (SerialPortInvalidPortException e) {
            throw new IOException("cannot open serial port " + path + ": " + e.getMessage()
                    + ". Give the port's path, e.g. /dev/ttyUSB0 or COM3 ('ports' lists them)", e);
        }
        port.setComPortParameters(settings.baud(), settings.dataBits(), stopBits(settings.stopBits()),
                parity(settings.parity()));
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, READ_SLICE_MILLIS, 0);
        // openPort()'s result is the truth; getLastErrorCode() is not reliable across platforms.
        if (!port.openPort()) {
            throw new IOException(openFailure(path, port.getLastErrorCode(), windows));
        }
        SerialLink link = new SerialLink(port, settings);
        return link;
    }

    /**
     * @param path the port as given
     * @param errorCode the operating system's error number for the failed open
     * @param windows whether this is Windows
     * @return the one-line error for a port that would not open: what the error number means, and the fix
     */
    static String openFailure(String path, int errorCode, boolean windows) {
        // 2 is "no such file" on Linux and macOS (ENOENT) and on Windows (ERROR_FILE_NOT_FOUND); 5 on Windows and
        // 13 on Linux and macOS are "access denied".
        if (errorCode == 2) {
            return "cannot open serial port " + path
                    + " (OS error 2): there is no such port. Check that the cable or USB"
                    + " adapter is plugged in and the port's name (Device Manager, under Ports, on"
                    + " Windows); 'ports' lists the ports this machine has";
        }
        String permission = windows ? "" : " (on Linux: sudo usermod -aG dialout $USER, then log in again)";
        return "cannot open serial port " + path + " (OS error " + errorCode + "): another program may hold it (close"
                + (windows ? " PuTTY, Tera Term" : " minicom, screen") + " or another khepera-link), or you may lack"
                + " permission" + permission;
    }

    private static int stopBits(int bits) {
        return bits == 2 ? SerialPort.TWO_STOP_BITS : SerialPort.ONE_STOP_BIT;
    }

    private static int parity(SerialSettings.Parity p) {
        return switch (p) {
            case NONE -> SerialPort.NO_PARITY;
            case ODD -> SerialPort.ODD_PARITY;
            case EVEN -> SerialPort.EVEN_PARITY;
            case MARK -> SerialPort.MARK_PARITY;
            case SPACE -> SerialPort.SPACE_PARITY;
        };
    }

    private LinkClosedException gone() {
        return new LinkClosedException("serial port " + settings.path() + " has gone: the USB adapter was unplugged,"
                + " or the far end of a virtual port closed; plug it back in and start again");
    }

    @Override
    protected int readSome(byte[] into, int timeoutMillis) throws IOException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (true) {
            if (closed) {
                throw new LinkClosedException("serial port " + settings.path() + " was closed");
            }
            int n = port.readBytes(into, into.length);
            if (n < 0) {
                throw gone();
            }
            if (n > 0 || System.nanoTime() >= deadline) {
                return n;
            }
        }
    }

    @Override
    protected int available() throws IOException {
        int n = port.bytesAvailable();
        if (n < 0) {
            throw gone();
        }
        return n;
    }

    @Override
    protected void writeBytes(byte[] bytes) throws IOException {
        if (closed) {
            throw new LinkClosedException("serial port " + settings.path() + " was closed");
        }
        int n = port.writeBytes(bytes, bytes.length);
        if (n != bytes.length) {
            throw gone();
        }
    }

    @Override
    public void addExitHook(Thread hook) {
        // jSerialComm runs these before it closes its ports at exit; a plain JVM hook would race it.
        SerialPort.addShutdownHook(hook);
    }

    @Override
    public void removeExitHook(Thread hook) {
        // jSerialComm cannot withdraw one: the hook stays, and does nothing once the robot is stopped.
    }

    @Override
    public String describe() {
        return settings.path() + " at " + settings.baud() + " baud";
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            port.closePort();
        }
    }
}
