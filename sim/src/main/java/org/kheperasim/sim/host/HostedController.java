package org.kheperasim.sim.host;

import org.kheperasim.sim.engine.RobotDriver;

/** A robot's controller as the run sees it, whichever way it runs: in a thread of its own, or stepped inline. */
public interface HostedController extends RobotDriver {
    /**
     * @return the controller's name in messages: its simple class name, with its robot's index when there are several
     *     (Name#3)
     */
    String name();

    /** @return the controller class */
    Class<?> type();

    /** @return where the controller is in its life */
    ControllerStatus status();

    /** @return what the controller threw, or null */
    Throwable failure();

    /** @return the last error reported for the controller (why it hung, broke a rule, ran out of heap), or null */
    String lastError();
}
