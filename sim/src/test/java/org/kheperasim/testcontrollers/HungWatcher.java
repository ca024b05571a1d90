package org.kheperasim.testcontrollers;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.api.Controller;

/**
 * Every 100 simulated ms, looks at the cores the operating system lets the thread of
 * {@link HungAfterPinning} run on (once it has told its id), and reports {@code freed LIST} as
 * soon as that is more than one core; after 30 simulated seconds without, {@code never freed LIST}.
 * Then it lets the stuck thread end. Linux; a trusted test controller.
 */
public class HungWatcher extends Controller {
    private int looks;
    private String last = "not told";

    /** @return the {@code Cpus_allowed_list} of a {@code status} file in /proc */
    static String allowed(Path status) throws IOException {
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("Cpus_allowed_list:")) {
                return line.substring("Cpus_allowed_list:".length()).trim();
            }
        }
        return "?";
    }

    @Override
    protected void doWork() {
        sleepMillis(100);
        String tid = System.getProperty("kheperasim.test.hungTid");
        try {
            if (tid != null && !Files.exists(Path.of("/proc/self/task", tid))) {
                print("gone (let out by another watcher)");
                killControl();
            } else if (tid != null) {
                last = allowed(Path.of("/proc/self/task", tid, "status"));
                if (last.contains("-") || last.contains(",")) {
                    print("freed " + last);
                    killControl();
                }
            }
            if (++looks == 300 && isActive()) {
                print("never freed " + last);
                killControl();
            }
        } catch (IOException e) {
            print("failed " + e);
            killControl();
        }
    }

    @Override
    protected void cleanup() {
        letOut();
    }

    /** Let {@link HungAfterPinning}'s thread out of its wait, if it is in it. */
    public static void letOut() {
        String port = System.getProperty("kheperasim.test.hungPort");
        if (port != null) {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), Integer.parseInt(port))) {
                System.clearProperty("kheperasim.test.hungPort");
            } catch (IOException e) {
                // it no longer waits
            }
        }
    }
}
