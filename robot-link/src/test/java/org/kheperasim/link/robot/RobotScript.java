package org.kheperasim.link.robot;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.kheperasim.link.fake.FakeKhepera;

/**
 * What a test does to the fake robot while a controller runs on it: the script waits for what the
 * robot receives (never for a fixed time, which a busy machine stretches), acts, and may end the
 * run. The pty tests' way to stage a scene.
 */
@FunctionalInterface
interface RobotScript {
    /** Waits for what the robot receives, at most this long (generous: a machine under load). */
    long LIMIT_NANOS = TimeUnit.SECONDS.toNanos(20);

    /** Nothing happens to the robot. */
    RobotScript NOTHING = (robot, run) -> { };

    void play(FakeKhepera robot, RobotRun run) throws Exception;

    /**
     * Runs {@code run} for at most {@code millis} while this script plays on {@code robot}.
     *
     * @return how the run ended
     * @throws AssertionError when the script failed (what it waited for never came)
     */
    static RobotRun.Result play(RobotScript script, FakeKhepera robot, RobotRun run, long millis) throws Exception {
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread scene = new Thread(() -> {
            try {
                script.play(robot, run);
            } catch (InterruptedException e) {
                // The run ended first.
            } catch (Throwable t) {
                failed.set(t);
                run.requestStop("the test's script failed");
            }
        }, "robot-script");
        scene.setDaemon(true);
        scene.start();
        RobotRun.Result r = run.run(millis);
        scene.interrupt();
        scene.join(5000);
        if (failed.get() != null) {
            throw new AssertionError("the test's script: " + failed.get().getMessage(), failed.get());
        }
        return r;
    }

    /** Waits until the robot has received {@code line} more than {@code times} times. */
    static void awaitReceived(FakeKhepera robot, String line, long times) throws InterruptedException {
        long until = System.nanoTime() + LIMIT_NANOS;
        while (count(robot, line) <= times) {
            if (System.nanoTime() > until) {
                throw new AssertionError("the robot did not receive " + line + " within 20 s; the last lines: " + tail(robot.received()));
            }
            Thread.sleep(5);
        }
    }

    /** Waits until the robot has received {@code n} more lines: a fault set for the next reply has been met. */
    static void awaitMoreLines(FakeKhepera robot, int n) throws InterruptedException {
        long want = robot.received().size() + n;
        long until = System.nanoTime() + LIMIT_NANOS;
        while (robot.received().size() < want) {
            if (System.nanoTime() > until) {
                throw new AssertionError("the robot received nothing more within 20 s; the last lines: " + tail(robot.received()));
            }
            Thread.sleep(5);
        }
    }

    /** @return how often the robot has received {@code line} */
    static long count(FakeKhepera robot, String line) {
        return robot.received().stream().filter(line::equals).count();
    }

    /** @return the last dozen lines of {@code lines} */
    static List<String> tail(List<String> lines) {
        return lines.subList(Math.max(0, lines.size() - 12), lines.size());
    }
}
