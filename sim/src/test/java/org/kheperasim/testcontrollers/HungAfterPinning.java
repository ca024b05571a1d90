package org.kheperasim.testcontrollers;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.api.Controller;

/**
 * Sleeps five times (so it has waited for its turn, and been pinned), reports its cores, then
 * waits in a library call that makes no API call, as a stuck controller would: for a connection
 * to a socket of its own. It tells its thread id ({@code kheperasim.test.hungTid}) and the socket's
 * port ({@code kheperasim.test.hungPort}); {@link HungWatcher#letOut} lets it end. A trusted test
 * controller (files, sockets); CpuAffinityTest.
 */
public class HungAfterPinning extends Controller {
    private int sleeps;

    @Override
    protected void doWork() {
        if (sleeps++ < 5) {
            sleepMillis(100);
            return;
        }
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            print("pinned " + HungWatcher.allowed(Path.of("/proc/thread-self/status")));
            System.setProperty("kheperasim.test.hungPort", String.valueOf(socket.getLocalPort()));
            System.setProperty("kheperasim.test.hungTid", Files.readSymbolicLink(Path.of("/proc/thread-self")).getFileName().toString());
            socket.accept().close();
        } catch (Exception e) {
            print("failed " + e);
        }
        killControl();
    }
}
