package org.kheperasim.testcontrollers;

import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Sleeps five times (so it has waited for its turn), starts a thread that sleeps 90 s of real time
 * (a daemon: it outlives the test's look at it on a machine however busy),
 * then reports the cores the operating system lets its own thread run on (Linux; a trusted run,
 * since it reads a file). CpuAffinityTest.
 */
public class CoreReporter extends Thread {
    private final MessagePasser mp;

    public CoreReporter(CurrentRobotState state, MessagePasser mp) {
        this.mp = mp;
    }

    @Override
    public void run() {
        try {
            for (int i = 0; i < 5; i++) {
                Thread.sleep(100);
            }
            // A thread it creates now starts on its core too (Linux hands the cores down); it outlives the run.
            Thread child = new Thread(() -> {
                try {
                    Thread.sleep(90_000);
                } catch (InterruptedException e) {
                    // ends
                }
            }, "pinned-child");
            child.setDaemon(true);
            child.start();
            for (String line : Files.readAllLines(Path.of("/proc/thread-self/status"))) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    mp.sendMessage("cores " + line.substring("Cpus_allowed_list:".length()).trim());
                }
            }
        } catch (Exception e) {
            mp.sendMessage("failed " + e);
        }
    }
}
