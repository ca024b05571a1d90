package edu.wsu.KheperaSimulator;

/**
 * The thread a backend starts for a {@link RobotController}: it zeroes the wheel positions, calls
 * the controller's {@code simStart()} and runs its loop, and stops the wheels on the way out,
 * however the loop ends. An exception
 * from the controller leaves {@link #run()} unchanged, for the backend to report.
 */
final class RobotControllerThread extends Thread {
    private final RobotController controller;
    private final CurrentRobotState state;

    /**
     * @param controller the initialised controller
     * @param state the robot it was initialised with
     * @param name the thread's name: the controller's simple class name
     */
    RobotControllerThread(RobotController controller, CurrentRobotState state, String name) {
        super(name);
        this.controller = controller;
        this.state = state;
    }

    /**
     * The backends' stop request (see {@code Controllers.requestStop}), the original's Halt: the
     * loop ends after the current {@code doWork()} and its pause, then {@code close()} runs. It does
     * not interrupt.
     */
    public void killControl() {
        controller.setFinished(true);
    }

    @Override
    public void run() {
        try {
            state.startRun();
            controller.runFromBackend();
        } finally {
            state.stopQuietly();
        }
    }
}
