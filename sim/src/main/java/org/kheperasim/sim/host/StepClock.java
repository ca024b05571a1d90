package org.kheperasim.sim.host;

/**
 * The simulated clock that a step controller's rewritten code sees while its {@code step()} runs:
 * the clocks read the step's time, a loop checkpoint stops a hung step, and what would block
 * (sleeping, starting a thread) is refused, since a step must return.
 */
final class StepClock implements SimClock.Clock {
    private final StepHost host;

    StepClock(StepHost host) {
        this.host = host;
    }

    /** A line the step's code printed, for the run's console. */
    void say(ConsoleLine.Kind kind, String text) {
        host.say(kind, text);
    }

    @Override
    public void sleepNanos(long nanos) {
        host.sleepNanos(nanos);
    }

    @Override
    public long nanoTime() {
        host.enter();
        long t = host.now();
        host.leave();
        return t;
    }

    @Override
    public long currentTimeMillis() {
        host.enter();
        long t = ControllerClock.EPOCH_MILLIS + host.now() / 1_000_000L;
        host.leave();
        return t;
    }

    @Override
    public void pause() {
        host.enter();
        host.leave();
    }

    @Override
    public void checkpoint() {
        host.checkpoint();
    }

    @Override
    public boolean onControllerThread() {
        return true;
    }

    @Override
    public void brokeRule(String what) {
        host.brokeRule(what);
    }

    @Override
    public boolean adopt(Thread thread) {
        throw new IllegalStateException("a step controller may not start threads: step() reads the sensors, sets the"
                + " motors and returns (use a Controller for a controller with threads)");
    }
}
