package org.kheperasim.link.fake;

import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.link.timing.LinkTiming;

/**
 * Try khepera-link by hand without a robot: starts socat and the fake robot, prints the port to
 * give to {@code --port}, and runs until killed. Argument: the baud whose wire time replies take
 * (0 for none). Run with the test classpath, e.g.
 * {@code mvn -o -q -pl robot-link exec:java -Dexec.classpathScope=test -Dexec.mainClass=org.kheperasim.link.fake.FakeRobotMain}.
 */
public final class FakeRobotMain {
    private FakeRobotMain() {
    }

    public static void main(String[] args) throws Exception {
        int baud = args.length > 0 ? Integer.parseInt(args[0]) : 38400;
        Path dir = Files.createTempDirectory("fake-khepera");
        try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, baud > 0 ? LinkTiming.atBaud(baud) : null)) {
            fake.robot().setProximity(10, 20, 30, 40, 50, 60, 70, 80);
            System.out.println("fake Khepera listening; use --port " + fake.hostPath());
            System.out.flush();
            while (true) {
                Thread.sleep(1000);
            }
        }
    }
}
