package org.kheperasim.link.fake;

import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.robot.PollBench;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;

/**
 * Prints the poll rate robot-link reaches over a socat pty pair against the fake robot, which
 * delays each reply by the exchange's wire time at the baud tried. Figures, not a test:
 * {@code mvn -o -q -pl robot-link exec:java -Dexec.classpathScope=test -Dexec.mainClass=org.kheperasim.link.fake.PollRateBench}.
 * Arguments: seconds per baud (default 5), then bauds (default 9600 38400 115200).
 */
public final class PollRateBench {
    private PollRateBench() {
    }

    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 5;
        int[] bauds = {9600, 38400, 115200};
        if (args.length > 1) {
            bauds = new int[args.length - 1];
            for (int i = 1; i < args.length; i++) {
                bauds[i - 1] = Integer.parseInt(args[i]);
            }
        }
        System.out.println("poll rate over a socat pty pair, fake robot delaying each reply by its wire time"
                + " (11 bits/char, 0.5 ms turnaround), " + seconds + " s each");
        for (int baud : bauds) {
            Path dir = Files.createTempDirectory("khepera-bench");
            LinkTiming timing = LinkTiming.atBaud(baud);
            try (FakeRobotOnPty fake = FakeRobotOnPty.start(dir, timing);
                    Session s = new Session(SerialLink.open(SerialSettings.khepera(fake.hostPath(), baud)), timing,
                            Session.Options.defaults())) {
                fake.robot().setProximity(1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000);
                fake.robot().setLight(500, 500, 500, 500, 500, 500, 500, 500);
                s.open();
                System.out.println(PollBench.measure(s, baud, (long) (seconds * 1000)).describe());
            }
        }
    }
}
