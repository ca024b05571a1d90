package org.kheperasim.link.fake;

import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import org.kheperasim.link.timing.LinkTiming;

/** A fake robot on the robot end of a socat pty pair; closing it ends socat. */
public final class FakeRobotOnPty implements AutoCloseable {
    private final PtyPair pty;
    private final FakeKhepera robot;

    private FakeRobotOnPty(PtyPair pty, FakeKhepera robot) {
        this.pty = pty;
        this.robot = robot;
    }

    /**
     * @param dir the test's own folder
     * @param timing wire timing for the replies, or null
     * @return socat running and the fake answering on its robot end
     */
    public static FakeRobotOnPty start(Path dir, LinkTiming timing) throws IOException, InterruptedException {
        PtyPair pty = PtyPair.open(dir);
        FakeKhepera robot = new FakeKhepera(new FileInputStream(pty.robot().toFile()),
                new FileOutputStream(pty.robot().toFile()), timing).start();
        return new FakeRobotOnPty(pty, robot);
    }

    /** @return the path robot-link opens */
    public String hostPath() {
        return pty.host().toString();
    }

    /** @return the fake robot */
    public FakeKhepera robot() {
        return robot;
    }

    /** @return the pty pair */
    public PtyPair pty() {
        return pty;
    }

    @Override
    public void close() throws InterruptedException {
        pty.kill();
        robot.close();
    }
}
