package edu.wsu.KheperaSimulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.binding.Controllers;

/**
 * A WSU controller run the way every backend runs a controller: {@code Controllers.instantiate},
 * {@code start()}, {@code Controllers.requestStop}, an uncaught-exception handler.
 */
@Timeout(value = 20, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuControllerRunTest {
    /** What the controllers below saw, in order. */
    static final List<String> LOG = Collections.synchronizedList(new ArrayList<>());
    static volatile CountDownLatch working;

    private final FakePort port = new FakePort();
    private final AtomicReference<Throwable> uncaught = new AtomicReference<>();

    private Thread start(Class<?> type) {
        LOG.clear();
        Controllers.check(type);
        Thread t = Controllers.instantiate(type, new org.kheperasim.api.CurrentRobotState(port), new MessagePasser(port));
        t.setUncaughtExceptionHandler((thread, e) -> uncaught.set(e));
        t.start();
        return t;
    }

    private Thread runToEnd(Class<?> type) throws InterruptedException {
        Thread t = start(type);
        t.join();
        return t;
    }

    /** Asks for a 50 ms pause in its constructor; stops itself after three steps. */
    public static class ThreeSteps extends RobotController {
        private int steps;

        public ThreeSteps() {
            setWaitTime(50);
        }

        @Override
        public void doWork() {
            steps++;
            LOG.add("doWork " + steps + " running=" + isRunning());
            setMotorSpeeds(steps, steps);
            if (steps == 3) {
                setFinished(true);
            }
        }

        @Override
        public void close() {
            LOG.add("close running=" + isRunning());
        }
    }

    @Test
    void theLoopIsDoWorkAndPauseUntilFinishedThenCloseOnce() throws Exception {
        Thread t = runToEnd(ThreeSteps.class);
        assertNull(uncaught.get());
        assertEquals("ThreeSteps", t.getName());
        assertEquals(List.of("doWork 1 running=true", "doWork 2 running=true", "doWork 3 running=true",
                "close running=false"), LOG);
        assertEquals(List.of(20L, 20L, 20L), port.sleeps,
                "the simulator's 20 ms overrides the constructor's setWaitTime, as in the original; the last step pauses too");
        assertEquals(List.of("1,1", "2,2", "3,3", "0,0"), port.speeds, "the wheels are stopped when the controller ends");
    }

    /** Calls simStart() from doWork, as code ported from the WSU simulator may; remembers itself. */
    public static class SimStarter extends RobotController {
        static volatile SimStarter last;
        private int steps;

        public SimStarter() {
            last = this;
        }

        @Override
        public void doWork() {
            simStart();
            LOG.add("doWork " + ++steps + " on " + Thread.currentThread().getName());
            setFinished(steps == 2);
        }

        @Override
        public void close() {
        }
    }

    /**
     * simStart() never starts the runner the backend attached, even while that runner looks
     * unstarted (as it does when a virtual thread runs its code): the backend starts it, once.
     */
    @Test
    void simStartLeavesTheAttachedRunnerToTheBackend() throws Exception {
        LOG.clear();
        Controllers.check(SimStarter.class);
        Thread t = Controllers.instantiate(SimStarter.class, new org.kheperasim.api.CurrentRobotState(port), new MessagePasser(port));
        t.setUncaughtExceptionHandler((thread, e) -> uncaught.set(e));
        SimStarter.last.simStart();
        assertEquals(Thread.State.NEW, t.getState(), "simStart() left the attached runner alone");
        t.start();
        t.join();
        assertNull(uncaught.get());
        assertEquals(List.of("doWork 1 on SimStarter", "doWork 2 on SimStarter"), LOG, "one runner ran the loop");
    }

    /** Calls simStart() from its constructor. */
    public static class StartsInConstructor extends RobotController {
        private int steps;

        public StartsInConstructor() {
            simStart();
        }

        @Override
        public void doWork() {
            LOG.add("doWork " + ++steps + " on " + Thread.currentThread().getName());
            setFinished(steps == 2);
        }

        @Override
        public void close() {
        }
    }

    /** simStart() in the constructor starts nothing of its own: the backend's runner runs the loop, once. */
    @Test
    void simStartInTheConstructorLeavesTheStartToTheBackend() throws Exception {
        LOG.clear();
        Thread t = Controllers.instantiate(StartsInConstructor.class, new org.kheperasim.api.CurrentRobotState(port),
                new MessagePasser(port));
        Thread.sleep(100);
        assertEquals(List.of(), LOG, "nothing ran before the backend started the controller");
        t.setUncaughtExceptionHandler((thread, e) -> uncaught.set(e));
        t.start();
        t.join();
        assertNull(uncaught.get());
        assertEquals(List.of("doWork 1 on StartsInConstructor", "doWork 2 on StartsInConstructor"), LOG);
    }

    /** Changes its pause from doWork. */
    public static class Slower extends RobotController {
        private int steps;

        public Slower() {
        }

        @Override
        public void doWork() {
            setWaitTime(++steps == 1 ? 100 : 0);
            setFinished(steps == 3);
        }

        @Override
        public void close() {
        }
    }

    @Test
    void setWaitTimeInDoWorkChangesThePause() throws Exception {
        runToEnd(Slower.class);
        assertEquals(List.of(100L), port.sleeps, "100 ms after the first step, no pause after the others");
    }

    /** Drives until it is halted. */
    public static class Forever extends RobotController {
        public Forever() {
        }

        @Override
        public void doWork() {
            setMotorSpeeds(5, 5);
            working.countDown();
        }

        @Override
        public void close() {
            LOG.add("close");
            setMotorSpeeds(0, 0);
        }
    }

    @Test
    void aStopRequestIsTheOriginalsHaltTheLoopEndsAndCloseRuns() throws Exception {
        working = new CountDownLatch(3);
        port.sleepsTakeRealTime = true;
        Thread t = start(Forever.class);
        working.await();
        assertTrue(Controllers.requestStop(t), "the runner has a killControl()");
        t.join();
        assertNull(uncaught.get());
        assertEquals(List.of("close"), LOG);
        assertEquals("0,0", port.lastSpeeds());
    }

    /** Sleeps in doWork with Thread.sleep, as student code does; an interruption is the backend stopping it. */
    public static class SleepsInDoWork extends RobotController {
        public SleepsInDoWork() {
        }

        @Override
        public void doWork() throws Exception {
            working.countDown();
            Thread.sleep(60_000);
        }

        @Override
        public void close() {
            LOG.add("close");
        }
    }

    @Test
    void anInterruptionThatStopsTheControllerIsNoFailure() throws Exception {
        working = new CountDownLatch(1);
        Thread t = start(SleepsInDoWork.class);
        working.await();
        Controllers.requestStop(t);
        t.interrupt();
        t.join();
        assertNull(uncaught.get(), "stopped, not failed");
        assertEquals(List.of("close"), LOG);
    }

    static final IOException BUG = new IOException("student bug");

    /** Throws a checked exception on its second step. */
    public static class Thrower extends RobotController {
        private int steps;

        public Thrower() {
        }

        @Override
        public void doWork() throws Exception {
            setMotorSpeeds(6, 6);
            if (++steps == 2) {
                throw BUG;
            }
        }

        @Override
        public void close() throws Exception {
            LOG.add("close");
            throw new IllegalStateException("close failed too");
        }
    }

    @Test
    void anExceptionEndsTheControllerIsReportedUnchangedAndTheRobotStops() throws Exception {
        Thread t = runToEnd(Thrower.class);
        assertFalse(t.isAlive());
        assertSame(BUG, uncaught.get(), "the controller's own exception reaches the backend, not a wrapper");
        assertEquals(List.of("close"), LOG, "close() still runs");
        assertEquals("close failed too", BUG.getSuppressed()[0].getMessage());
        assertEquals("0,0", port.lastSpeeds(), "the wheels were stopped");
        assertTrue(port.speeds.contains("6,6"));
        // The application is alive: this test goes on, and another controller runs.
        runToEnd(ThreeSteps.class);
        assertEquals(4, LOG.size());
    }

    /** Ends normally, but close() throws. */
    public static class BadClose extends RobotController {
        public BadClose() {
        }

        @Override
        public void doWork() {
            setFinished(true);
        }

        @Override
        public void close() {
            throw new ArithmeticException("/ by zero");
        }
    }

    @Test
    void anExceptionFromCloseIsReportedToo() throws Exception {
        runToEnd(BadClose.class);
        assertInstanceOf(ArithmeticException.class, uncaught.get());
        assertEquals("0,0", port.lastSpeeds());
    }

    /** Reads its wheels at the start of the run. */
    public static class Odometry extends RobotController {
        public Odometry() {
        }

        @Override
        public void doWork() {
            LOG.add(getLeftWheelPosition() + " " + getRightWheelPosition());
            setFinished(true);
        }

        @Override
        public void close() {
        }
    }

    @Test
    void wheelPositionsAreZeroWhenTheRunStarts() throws Exception {
        port.leftPosition = 777;
        port.rightPosition = -5;
        runToEnd(Odometry.class);
        assertEquals(List.of("0 0"), LOG);
    }
}
