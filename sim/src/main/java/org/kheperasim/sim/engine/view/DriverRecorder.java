package org.kheperasim.sim.engine.view;

/**
 * Hears everything a run's drivers (its controllers) do to the world, in the order the engine sees
 * it: the commands that reach a robot's link, the reads that change what a listener sees (a poll reply
 * brought in early, a vision turret's image taken), the emergency stops, and each driver's wake time as the
 * engine reads it at the start and after every turn. That is all that makes one run differ from
 * another with the same arena, seed and settings, so a run replayed from it, open loop and without
 * the controllers, computes the same world (see {@code org.kheperasim.sim.commandlog}).
 *
 * <p>Called by whoever holds the turn, one call at a time.
 */
public interface DriverRecorder {
    /**
     * A driver's wake time, as the engine reads it next.
     *
     * @param robot     the robot's index
     * @param sliceTick the tick of the turn that has just ended, or -1 for the wake at the run's start
     * @param wakeNanos the driver's wake time, ns ({@link Long#MAX_VALUE} once it has ended)
     */
    void wake(int robot, long sliceTick, long wakeNanos);

    /** A controller asked for wheel speeds at {@code now}, ns; units. Calls that change nothing are not told. */
    void speeds(int robot, long now, int left, int right);

    /** A controller set the position counters at {@code now}, ns; pulses. */
    void positions(int robot, long now, int left, int right);

    /** A controller moved the arm at {@code now}, ns, to a position 0..255 (larger = lower). */
    void arm(int robot, long now, int position);

    /** A controller opened or closed the fingers at {@code now}, ns. */
    void fingers(int robot, long now, boolean closed);

    /**
     * A controller's read at {@code now} brought a poll reply in before the engine's tick reached it
     * (its calls reach past the tick): from then on the engine's own tick shows that reply too.
     *
     * @param robot the robot
     * @param now   the controller's simulated time, ns
     * @param step  which reply
     */
    void delivered(int robot, long now, org.kheperasim.link.timing.PollStep step);

    /**
     * A controller's read at {@code now} made the robot's K213 vision turret take the image of that
     * period (the first read in it): the image, from the world as it stands then, is what the trace's
     * vision line shows from then on. Later reads in the same period change nothing and are not told.
     *
     * @param robot the robot
     * @param now   the controller's simulated time, ns
     */
    void image(int robot, long now);

    /**
     * The run was stopped early (a signal, the window's Stop: the wall clock decides when): it ends at
     * {@code nanos}, not where it was set to end.
     *
     * @param nanos simulated time, ns
     */
    void stoppedAt(long nanos);

    /** The robot's wheels were stopped at once and its link cleared: its controller ended, failed or was stopped. */
    void emergencyStop(int robot);
}
