package org.kheperasim.link.robot;

/**
 * Calls robot-link makes into a controller's own methods ({@code start()}, {@code killControl()},
 * {@code interrupt()}, {@code setUncaughtExceptionHandler}): a class may override each, so each runs on
 * a daemon thread of its own, never on the thread that watches the run and stops the robot; one that
 * spins or blocks is waited for a bounded time, one that throws has its throwable kept.
 */
final class ControllerCalls {
    private ControllerCalls() {
    }

    /**
     * What came of a call.
     *
     * @param returned true when it returned or threw within the time given
     * @param thrown what it threw, or null
     */
    record Outcome(boolean returned, Throwable thrown) {
    }

    /**
     * @param name the controller's name, for the thread's
     * @param millis how long to wait for it, ms (at least 1)
     * @param call the call
     * @return whether it returned in time, and what it threw
     */
    static Outcome call(String name, long millis, Runnable call) throws InterruptedException {
        Throwable[] thrown = new Throwable[1];
        // No inherited thread-locals: the call is the controller's, not robot-link's.
        Thread t = new Thread(null, () -> {
            try {
                call.run();
            } catch (Throwable e) {
                thrown[0] = e;
            }
        }, "khepera-controller-call-" + name, 0, false);
        t.setDaemon(true);
        t.start();
        t.join(StrictMath.max(1, millis));
        boolean returned = !t.isAlive();
        return new Outcome(returned, returned ? thrown[0] : null);
    }

    /**
     * @param name the controller's name
     * @param e what its code threw
     * @return how the throwable describes itself ({@code toString()}, its class's to override), or its class's name
     *     when that throws or does not return within a second
     */
    static String describe(String name, Throwable e) throws InterruptedException {
        String[] text = new String[1];
        Outcome o = call(name, 1000, () -> text[0] = String.valueOf(e));
        return o.returned() && o.thrown() == null && text[0] != null ? text[0] : e.getClass().getName();
    }
}
