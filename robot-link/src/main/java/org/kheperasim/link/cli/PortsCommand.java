package org.kheperasim.link.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import org.kheperasim.link.io.SerialLink;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code ports}: list the serial ports. */
@Command(name = "ports", mixinStandardHelpOptions = true, description = "List the serial ports this machine has.")
final class PortsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        List<SerialLink.PortInfo> ports = SerialLink.listPorts();
        if (ports.isEmpty()) {
            out.println("no serial ports found. Plug in the USB-serial adapter (on Linux it appears as /dev/ttyUSB0"
                    + " or /dev/ttyACM0).");
        }
        for (SerialLink.PortInfo p : ports) {
            out.println(p.path() + "  " + p.description());
        }
        out.println("(virtual ports, such as a socat pty pair, are not listed but open by path with --port)");
        return 0;
    }
}
