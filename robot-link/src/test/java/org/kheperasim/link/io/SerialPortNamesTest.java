package org.kheperasim.link.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Locale;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.kheperasim.link.cli.Main;

/**
 * A student's port name from another system: {@code COM3} (what Windows's Device Manager shows, and what a
 * student copies from a classmate) given on Linux or macOS is one line naming the port and saying what a
 * port is called here, exit status 2, not jSerialComm's "invalid port descriptor" followed by the advice to
 * give COM3. On Windows itself a COM name goes to jSerialComm as it is; that a port which is not there says
 * so (OS error 2) is checked on the message, as this machine cannot open a Windows port.
 */
class SerialPortNamesTest {
    private static boolean windows() {
        return System.getProperty("os.name", "").toLowerCase(Locale.ROOT).startsWith("windows");
    }

    @Test
    void aWindowsPortNameElsewhereSaysWhatAPortIsCalledHere() {
        Assumptions.assumeFalse(windows(), "on Windows COM3 is a port name");
        for (String name : new String[] {"COM3", "com3", "COM12", "\\\\.\\COM10"}) {
            IOException e = assertThrows(IOException.class, () -> SerialLink.open(SerialSettings.khepera(name, 38400)));
            String m = e.getMessage();
            assertTrue(m.startsWith("cannot open serial port " + name + ": COM names are Windows's"), m);
            assertTrue(m.contains("/dev/ttyUSB0") && m.contains("'ports' lists"), m);
            assertFalse(m.contains("\n"), "one line: " + m);
        }
    }

    @Test
    void theCommandLineRefusesItWithExitStatusTwoAndOneLine() {
        Assumptions.assumeFalse(windows(), "on Windows COM3 is a port name");
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.execute(new String[] {"run", "--port", "COM3", "--controller", "WallFollower"},
                new ByteArrayInputStream(new byte[0]), new PrintWriter(out), new PrintWriter(err));
        assertEquals(2, code, out + "" + err);
        String e = err.toString().strip();
        assertTrue(e.startsWith("khepera-link: error: cannot open serial port COM3: COM names are Windows's"), e);
        assertEquals(1, e.lines().count(), e);
    }

    @Test
    void aNameLikeAWindowsPortIsAPathElsewhere() {
        Assumptions.assumeFalse(windows(), "on Windows COM3 is a port name");
        IOException e = assertThrows(IOException.class, () -> SerialLink.open(SerialSettings.khepera("com-port", 38400)));
        assertTrue(e.getMessage().contains("com-port: it does not exist"), e.getMessage());
    }

    @Test
    void aPortThatIsNotThereOrIsHeldSaysWhich() {
        String absent = SerialLink.openFailure("COM3", 2, true);
        assertTrue(absent.startsWith("cannot open serial port COM3 (OS error 2): there is no such port"), absent);
        assertTrue(absent.contains("Device Manager"), absent);
        String held = SerialLink.openFailure("COM3", 5, true);
        assertTrue(held.contains("another program may hold it (close PuTTY, Tera Term or another khepera-link)"), held);
        assertFalse(held.contains("usermod"), "no Linux advice on Windows: " + held);
        String linux = SerialLink.openFailure("/dev/ttyUSB0", 13, false);
        assertTrue(linux.contains("usermod -aG dialout"), linux);
    }
}
