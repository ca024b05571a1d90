package org.kheperasim.api.binding;

import org.kheperasim.api.StepController;
import org.kheperasim.api.spi.RobotPort;

/**
 * Runs a {@link StepController} in a thread of its own, for a backend that does not step
 * controllers inline (robot-link on the real robot): {@code begin()}, then {@code stepOnce()} and a
 * sleep of the period until asked to stop, then {@code end()}. The timing is the step contract's:
 * the next step comes one period after this one's last call.
 */
public final class StepRunner extends Thread {
    private final StepController controller;
    private final RobotPort port;
    private volatile boolean active = true;

    /**
     * @param controller the controller to step
     * @param port the robot it drives (its clock: the simulator's or the real one)
     */
    public StepRunner(StepController controller, RobotPort port) {
        this.controller = controller;
        this.port = port;
        setName(controller.getClass().getSimpleName());
    }

    /** @return the controller it steps */
    public StepController controller() {
        return controller;
    }

    @Override
    public void run() {
        controller.begin();
        while (active) {
            controller.stepOnce();
            try {
                port.sleep(controller.period());
            } catch (InterruptedException e) {
                active = false;
                Thread.currentThread().interrupt();
            }
        }
        controller.end();
    }

    /** Stop after the current step (the Appendix's name for it, which backends call). */
    public void killControl() {
        active = false;
    }
}
