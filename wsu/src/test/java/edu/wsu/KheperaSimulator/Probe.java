package edu.wsu.KheperaSimulator;

/** A controller whose methods the tests call from their own thread; its loop does nothing. */
public class Probe extends RobotController {
    public Probe() {
    }

    /** @return a probe connected to {@code port}, as the simulator connects a controller */
    static Probe on(FakePort port) {
        Probe p = new Probe();
        p.initialize("Probe", new CurrentRobotState(port), RobotController.SIMULATOR_WAIT_MS);
        return p;
    }

    @Override
    public void doWork() {
        setFinished(true);
    }

    @Override
    public void close() {
    }
}
